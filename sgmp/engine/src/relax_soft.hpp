#pragma once
/// @file relax_soft.hpp
/// The relaxation's soft stage (relax.cpp), which relax_pack (relax_pack.cpp) runs before
/// the hard-sphere finish and settling. Internal to the engine.
#include <vector>

#include "sgmp/engine/relax.hpp"

namespace sgmp::engine {

/// Overlap the hard-sphere finish leaves at most, over d.
inline constexpr double kFinishToleranceOverD = 1e-10;

/// The soft relaxation of every stage; leaves the soft pack's positions in `particles`.
void relax_soft(std::vector<Particle>& particles, const Container& container,
                const RelaxParams& params, double diameter, RelaxStats& stats,
                const RelaxProgressCallback& progress);

}  // namespace sgmp::engine
