#pragma once
/// @file contact_model.hpp
/// The contact models (`--contact`, ProtocolParams::contact): what becomes of a particle
/// that the protocol (protocol.hpp) leaves resting — no free arc, stalled, or at the move
/// limit. Particles fixed by the floor or a wall are left as they are.
///
///  - **none** (the thesis): the particle stays where the protocol left it.
///  - **settle** (§10.2): the particle is dropped exactly onto its first contact below
///    (closing the gap a step fall leaves; the floor fixes it), then rolled down the
///    meridian of |p − c_j| = r + r_j over that support j until it touches a second
///    sphere, the floor or a wall (`roll_over_support`). If it would reach the support's
///    equator first it stays where the drop put it (rolling further would be a fall the
///    protocol has already ruled out).
///  - **roll**: dropped the same way, then rolled on over the settled spheres until it
///    rests stably on three of them, or touches the floor or a wall (rolling.hpp,
///    `roll_to_rest`).
///
/// Both rolls end each leg at the first contact along its arc, found in closed form, and
/// refuse an end that overlaps a settled sphere by more than rounding (the guard
/// `clear_at`, contact_search.hpp).
#include "sgmp/engine/protocol.hpp"
#include "sgmp/engine/protocol_params.hpp"
#include "sgmp/engine/settled_grid.hpp"
#include "sgmp/pack/geometry.hpp"

namespace sgmp::engine {

/// Applies `model` to a particle of radius r resting at c among the spheres of `grid`
/// (radii ≤ r_max) in `container`; `reason` and `moves` are the protocol's. The outcome's
/// reason becomes Floor or Wall when the model brings the particle there.
DropOutcome apply_contact_model(ContactModel model, const SettledGrid& grid,
                                const Container& container, double r_max, const Vec3& c, double r,
                                StopReason reason, long moves);

/// The settle model's roll: a particle of radius r at c, touching `support` from above,
/// rolls down over it. The centre moves on the sphere of radius D = r + r_j about the
/// support: p(φ) = c_j + D (sin φ·u + cos φ·ŷ), φ from its current value φ0 towards the
/// equator π/2, u the horizontal unit vector from c_j to the centre. Against another
/// sphere k (a = c_j − c_k, D_k = r + r_k):
///   |p(φ) − c_k|² − D_k² = A sin φ + B cos φ − C = R cos(φ − α) − C,
///   A = 2D a·u, B = 2D a_y, C = D_k² − |a|² − D², R = √(A² + B²), α = atan2(A, B),
/// which turns negative (contact) at φ = α + acos(C / R). The floor is met at
/// cos φ = (floor + r − y_j)/D, a wall at sin φ = (wall ∓ r − x_j)/(D u_x) (same for z).
/// Returns the centre at the first of these, or c when none comes before the equator,
/// when c is exactly on top of the support, or when the end fails the overlap guard.
///
/// The path is the first leg of `roll_to_rest` on one support, but the two are kept apart:
/// that leg is written in the roll's own arc form p = c_j + D (cos ψ·n + sin ψ·t) from the
/// current contact normal n, and its root search treats a tangent start differently.
/// Settling through it moves centres by rounding (up to 1.6·10⁻¹⁴) in every settle pack
/// and, through later choices, changed 60 of 27,240 spheres by more than 10⁻¹² (up to
/// 0.38) in 44 settle packs (N = 300 and 1002, every arrangement) — not the same packs.
Vec3 roll_over_support(const SettledGrid& grid, const Container& container, double r_max,
                       const Vec3& c, double r, const Sphere& support);

}  // namespace sgmp::engine
