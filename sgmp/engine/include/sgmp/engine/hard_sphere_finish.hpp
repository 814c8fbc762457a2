#pragma once
/// @file hard_sphere_finish.hpp
/// Turns a soft pack (the small overlaps left by a soft-contact relaxation) into a
/// hard-sphere pack without undoing its structure.
///
/// Spheres are placed one by one in order of increasing centre height (ties by index); the
/// spheres placed before stay where they are. Sphere i starts at its soft position c,
/// moved inside the walls and onto the floor (x, z clamped to [wall + r, wall − r],
/// y ≥ floor + r). Then, up to `kFinishProjections` times, c is pushed straight away from
/// the placed sphere j it overlaps most, to touching: c ← cⱼ + (rᵢ + rⱼ)·(c − cⱼ)/|c − cⱼ|,
/// and put inside again. Each push moves it by the overlap δ = rᵢ + rⱼ − |c − cⱼ| — a
/// displacement of the order of the soft overlaps, along the contact normal, so a contact
/// stays a contact. A sphere still overlapping after that (wedged between a wall and a
/// sphere, say) is lifted straight up to the lowest height at which it overlaps no placed
/// sphere (settled_grid.hpp, `lowest_free_height`), which always exists.
///
/// "Overlap" means deeper than `tolerance`; afterwards no pair overlaps by more than
/// `tolerance` plus rounding (≈1e-16 relative) and every sphere is inside the container.
/// Each sphere moves by about the sum of the overlaps beneath it.
#include <cstddef>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::engine {

struct FinishStats {
    std::size_t lifted = 0;  ///< spheres that needed the vertical lift
    double move_max = 0.0;   ///< largest displacement of a sphere
    double move_sum = 0.0;   ///< sum of the displacements
};

/// Pushes away from the most overlapped sphere tried before the vertical lift.
inline constexpr int kFinishProjections = 100;

FinishStats finish_as_hard_spheres(std::vector<Particle>& particles, const Container& container,
                                   double tolerance);

}  // namespace sgmp::engine
