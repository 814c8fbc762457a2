#pragma once
/// @file pack.hpp
/// A pack: its particles and the provenance of how it was made.

#include <vector>

#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp {

struct Pack {
    std::vector<Particle> particles;
    Metadata metadata;
};

/// Mean diameter 2·<r> (the length unit of g(r) for polydisperse packs); 0 for an empty pack.
double mean_diameter(const Pack& pack);

}  // namespace sgmp
