#pragma once
/// @file rolling.hpp
/// Rolling a resting particle down over the settled spheres until it rests stably on three
/// of them (or reaches the floor or a wall) — the `--contact roll` model, a fuller reading of
/// the §10.2 contact model in the manner of sequential-deposition packings (Visscher &
/// Bolsterli 1972).
///
/// The particle (radius r) moves quasi-statically under gravity (−y), always touching its
/// supports (contact distance D_j = r + r_j):
///  - on one support j it rolls down the meridian of the sphere |p − c_j| = D_j until it
///    touches a second sphere, or until it reaches the support's equator (where the contact
///    force vanishes), from where it falls straight down to its next contact;
///  - on two supports j, k it rolls along the circle where both spheres meet, downhill,
///    while the support forces stay compressive — ŷ's part normal to the roll direction t,
///    ŷ − (ŷ·t)t = α n_j + β n_k with α, β ≥ 0 (n: unit contact normals) — until it touches
///    a third sphere, reaches the circle's lowest point (it rests on two), or a force
///    vanishes (it goes on rolling on the other support alone);
///  - on three supports it is stable when ŷ = α n_j + β n_k + γ n_l with α, β, γ ≥ 0; else it
///    leaves the support with the most negative coefficient and rolls on the other two.
/// Touching the floor or a wall ends the roll (they fix particles, thesis §4.2). Each leg
/// ends at the first contact along its arc, found in closed form (sphere: K + R cos(φ − α)
/// = 0; floor, walls: linear in cos φ, sin φ), so no overlap is ever made; a leg whose end
/// would overlap by more than rounding is not taken.
#include <vector>

#include "sgmp/engine/settled_grid.hpp"
#include "sgmp/pack/geometry.hpp"

namespace sgmp::engine {

enum class RollEnd {
    Stable,   ///< rests on its supports (three, or two at the bottom of their circle)
    Floor,    ///< touched the floor
    Wall,     ///< touched a wall
    Stopped,  ///< step limit or a degenerate configuration: left where it was
};

struct RollResult {
    Vec3 center;
    RollEnd end = RollEnd::Stopped;
};

/// Rolls a particle of radius r centred at c, touching `support` (a sphere of `grid`), to
/// rest. `r_max` bounds the grid's radii.
RollResult roll_to_rest(const SettledGrid& grid, const Container& container, double r_max,
                        const Vec3& c, double r, const Sphere& support);

}  // namespace sgmp::engine
