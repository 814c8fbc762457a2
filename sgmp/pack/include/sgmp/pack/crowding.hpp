#pragma once
/// @file crowding.hpp
/// The physical limit on how many sphere centres crowd together, checked in O(N) before
/// any pair search, so that a pair pass stays O(N) in time and memory however a file's
/// spheres are clumped (8,000 spheres at one point would otherwise make 3.2·10⁷ pairs).
///
/// The rule. Let r_min be the smallest radius. If no two spheres overlap by more than
/// r_min (depth r_i + r_j − |c_i − c_j| ≤ r_min), every two centres are at least
/// r_i + r_j − r_min ≥ r_min apart, so balls of radius r_min / 2 around them are disjoint.
/// Those around the centres in a cube of side h = 2·r_min lie in the cube of side
/// h + r_min = 3·r_min about it, so there are at most (3·r_min)³ / (π/6 · r_min³) =
/// 162/π < 52 of them: kMaxCentresPerCube. A cube of the grid of side 2·r_min holding more
/// centres has a pair overlapping by more than the smallest radius, around a sphere whose
/// overlaps make the pair metrics (coordination, g(r), overlap counts) meaningless.
/// Every pack of hard spheres, and every pack whose overlaps are shallower than r_min,
/// passes; in one that passes, a pair pass of reach R meets at most
/// kMaxCentresPerCube · (R / (2·r_min) + 2)³ candidates per sphere.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "sgmp/pack/particle.hpp"

namespace sgmp {

/// The most centres a cube of side 2·r_min holds unless two spheres overlap by more than
/// r_min: ⌊162/π⌋.
inline constexpr std::size_t kMaxCentresPerCube = 51;

/// A cube of side 2·r_min over-full: `index` of its first sphere (smallest index) and how
/// many centres it holds.
struct Crowding {
    std::size_t index = 0;
    std::size_t centres = 0;
    double cube_side = 0.0;  ///< 2·r_min
};

/// The first over-full cube of the grid of side 2·r_min (aligned at the origin), by
/// the smallest index of its spheres, or nothing when every cube holds at most
/// kMaxCentresPerCube centres (or a radius is not positive and finite: left to the
/// callers' own checks). O(N log N) time (a sort), O(N) memory.
std::optional<Crowding> overcrowded_cube(const std::vector<Particle>& particles);

}  // namespace sgmp
