#pragma once
/// @file hard_sphere_settle.hpp
/// Settles a hard-sphere pack under gravity into a frictionless mechanical equilibrium by
/// sequential linear programming (after Donev, Torquato, Stillinger & Connelly, J. Comput.
/// Phys. 197, 139, 2004, with gravity as the objective).
///
/// Each iteration solves, for displacements Δᵢ of every sphere (lengths over d, the scale
/// diameter; wᵢ = (dᵢ/d)³ the weights in m·g),
///
///     minimise Σᵢ wᵢ·Δᵢ,y
///     subject to  nᵢⱼ·(Δⱼ − Δᵢ) ≥ −hᵢⱼ   for every pair with gap hᵢⱼ < 2√3·s,
///                 the walls and the floor (bounds on Δᵢ), |Δᵢ,ₖ| ≤ s (trust region),
///
/// with nᵢⱼ the unit vector from i to j, and moves every sphere by Δ. Moves that change no
/// energy (a free column sliding sideways on the frictionless floor) are neutral, and the LP
/// may take them, within the trust region; in a jammed pack such zero modes are rare. (A
/// small cost on horizontal moves would remove them, but it multiplies the simplex pivots
/// by about 35.) Because
/// |cⱼ − cᵢ + Δⱼ − Δᵢ| ≥ nᵢⱼ·(cⱼ − cᵢ + Δⱼ − Δᵢ), the linearised constraint is
/// conservative: a step never creates an overlap (pairs farther than 2√3·s cannot meet
/// within the trust region), so every iterate is a hard-sphere pack and the potential
/// energy Σ wᵢ yᵢ falls monotonically. At an optimum Δ = 0 the LP's multipliers λᵢⱼ ≥ 0 are
/// frictionless contact forces balancing every weight: the pack is an equilibrium.
///
/// Trust region: doubled (up to `trust_max`) while more than 2 % of the spheres move the
/// full s vertically (a collective fall), divided by 4 when a step lowers the energy by
/// less than 10⁻⁴·s m·g (the energy's slope along the best step, which vanishes at an
/// equilibrium); the settling ends when s falls below
/// `trust_min`, or after `max_iterations`. The LP is COIN-OR CLP's: the first by the primal
/// simplex from the feasible point Δ = 0 (a values pass), each later one by the dual simplex
/// warm-started from the previous basis (pairs keyed by their sphere indices), on one
/// thread in a fixed order: the same pack gives the same bytes.
///
/// Multipliers: with u at an optimum strictly inside its trust box, the KKT conditions
/// read wᵢ·ŷ = Σⱼ λᵢⱼ·(−nᵢⱼ) + Σ_walls z·n_wall: the rows' multipliers λ = −y (CLP's row
/// duals y ≤ 0 on active ≤ rows) and the reduced costs z of the wall-held columns are the
/// contact forces, in m·g (the objective is in m·g per unit of u).
#include <cstddef>
#include <functional>
#include <vector>

#include "sgmp/engine/equilibrium_certificate.hpp"
#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::engine {

struct SettleOptions {
    double trust_start = 0.02;  ///< initial trust region s, over d
    double trust_max = 0.2;     ///< largest s, over d
    double trust_min = 1e-9;    ///< the settling ends when s is below this, over d
    int max_iterations = 5000;
    /// Called after every LP with the iteration count and the trust region (over d).
    std::function<void(int, double)> progress;
};

struct SettleStats {
    int iterations = 0;
    bool converged = false;    ///< ended by the trust region, not by the iteration bound
    double energy_drop = 0.0;  ///< Σ wᵢ·(yᵢ before − yᵢ after) / d, in m·g·d
    double move_max = 0.0;     ///< largest displacement of a sphere, over d
    double lp_seconds = 0.0;   ///< time in the LP solver (not recorded in packs)
    long long lp_pivots = 0;   ///< simplex iterations over all LPs
    /// The last LP's multipliers: λᵢⱼ ≥ 0 of the pair rows and the reduced costs of the
    /// columns held by a wall or the floor, the contact forces in m·g of the equilibrium
    /// found (the certificate's witness, equilibrium_certificate.hpp).
    std::vector<ContactForce> forces;
};

/// Settles `particles` (scale diameter `diameter`, no overlaps deeper than rounding) in
/// `container` as above. Particle order, ids, radii and colours are kept.
SettleStats settle_hard_spheres(std::vector<Particle>& particles, const Container& container,
                                double diameter, const SettleOptions& options = {});

}  // namespace sgmp::engine
