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

/// The promise of the rolling contact model (`--contact roll`, exact fall): every sphere
/// rests on the floor or a wall (gap ≤ contact_tolerance), or on spheres placed before it
/// (lower id; surface gap ≤ contact_tolerance) whose unit contact normals
/// n_k = (c_i − c_k)/|c_i − c_k| hold it in frictionless equilibrium under gravity: the
/// upward unit vector is a non-negative combination ŷ = Σ λ_k n_k of three of them, each
/// λ_k ≥ −force_tolerance (a 3×3 solve per triple of supports).
///
/// Two supports are not enough: a compressive pair balances gravity only when the centre
/// is at the top of the circle where both spheres meet (ŷ in the plane of the normals and
/// between them), and there any displacement along that circle lowers the sphere — an
/// unstable rest that the roll leaves. (The bottom of the circle needs a pulling support.)
struct RestCheck {
    /// Spheres not resting as above.
    std::size_t unrested = 0;
    /// Of these, the ones touching fewer than three earlier spheres.
    std::size_t fewer_than_three = 0;
    /// Index (into `particles`) of the first unrested sphere, or particles.size().
    std::size_t first = 0;
};

RestCheck check_rolled_rest(const std::vector<Particle>& particles, const Container& container,
                            double contact_tolerance, double force_tolerance);

}  // namespace sgmp::engine
