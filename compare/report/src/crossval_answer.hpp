#pragma once
/// @file crossval_answer.hpp
/// The report's first section: one sentence per SGMP mode, saying what it stands in for, at
/// which counts, on how many of the metrics judged there, with how many seeds, where its
/// packs cannot be mechanically stable, and how its time compares with the pours'.

#include <sstream>

#include "sgmp/report/crossval.hpp"

namespace sgmp::report {

/// Below this mean coordination at δ = 10⁻³·d (the DEM pours' mean overlap depth) no
/// packing of rigid frictional spheres can be in equilibrium: Maxwell's count for
/// frictional spheres in 3D needs Z ≥ 4 (6 for frictionless ones; a certified pack proves
/// its equilibrium directly, wall contacts included).
inline constexpr double kLeastStableFrictionalZ = 4.0;

/// "## The answer" and its sentences.
void answer_markdown(std::ostringstream& md, const CrossValidation& cv);

}  // namespace sgmp::report
