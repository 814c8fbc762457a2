#pragma once
/// @file pack_checks.hpp
/// The three invariants every finished SGMP pack satisfies, checked with the neighbour grid
/// (O(N)): no overlapping pair, every sphere inside the container, every sphere supported.
#include <cstddef>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::engine {

struct PackCheck {
    /// Pairs with surface gap |ci − cj| − ri − rj < −overlap_tolerance.
    std::size_t overlaps = 0;
    /// Most negative surface gap of any pair (0 when none is negative).
    double worst_gap = 0.0;
    /// Spheres crossing a wall or the floor by more than overlap_tolerance.
    std::size_t outside = 0;
    /// Spheres with no support: not within support_tolerance of the floor, a wall, or a
    /// sphere whose centre is not higher (surface gap ≤ support_tolerance).
    std::size_t unsupported = 0;
};

PackCheck check_pack(const std::vector<Particle>& particles, const Container& container,
                     double overlap_tolerance, double support_tolerance);

}  // namespace sgmp::engine
