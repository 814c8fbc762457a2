#pragma once
/// @file rolling.hpp
/// Rolling a resting particle down over the settled spheres until it rests stably on three
/// of them (or reaches the floor or a wall) — the `--contact roll` model, a fuller reading of
/// the §10.2 contact model in the manner of sequential-deposition packings (Visscher &
/// Bolsterli 1972).
///
/// The particle (radius r) moves quasi-statically under gravity (−y), always touching its
/// supports (contact distance D_j = r + r_j). Before each leg the motion is chosen as the
/// active set of the frictionless contact problem: the subset of the current contacts it
/// keeps, with compressive support forces, a downhill direction along their constraints,
/// and no other current contact approached (pairs are tried before single supports):
///  - on three supports it is stable when ŷ = α n_j + β n_k + γ n_l with α, β, γ ≥ 0
///    (n: unit contact normals, −10⁻¹² allowed for rounding);
///  - on two supports j, k it rolls along the circle where both spheres meet, downhill,
///    while ŷ − (ŷ·t)t = α n_j + β n_k with α, β ≥ 0 (t the roll direction), until it
///    touches a third sphere or a force vanishes (then it goes on with the other support).
///    Two compressive supports balance gravity only at the top of that circle, where every
///    displacement along it goes down: that rest is unstable and the roll goes on (either
///    way is downhill; the one clear of the other contacts is taken). The bottom of the
///    circle would need a pulling support, so no sphere ends on two spheres alone;
///  - on one support j it rolls down the meridian of |p − c_j| = D_j until it touches a
///    second sphere, or until it reaches the support's equator (where the contact force
///    vanishes), from where it falls straight down to its next contact. Exactly on top of
///    the support it rolls off along +x;
///  - with no compressive support it falls straight down.
/// Touching the floor or a wall ends the roll (they fix particles, thesis §4.2). Each leg
/// ends at the first contact along its arc, found in closed form (sphere: K + R cos(φ − α)
/// = 0; floor, walls: linear in cos φ, sin φ), so no overlap is ever made; a leg whose end
/// would overlap by more than rounding is not taken (the roll then stops, RollEnd::Stopped,
/// as it does after 1000 legs or in a degenerate configuration — none is known to occur).
#include <vector>

#include "sgmp/engine/settled_grid.hpp"
#include "sgmp/pack/geometry.hpp"

namespace sgmp::engine {

enum class RollEnd {
    Stable,   ///< rests on three supports in frictionless equilibrium
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
