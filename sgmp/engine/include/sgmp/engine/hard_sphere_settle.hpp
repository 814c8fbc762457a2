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
/// equilibrium), and doubled after 8 steps in a row that did neither (a steady creep);
/// the settling ends when s falls below
/// `trust_min`, or after `max_iterations`. The LP is COIN-OR CLP's: the first by the primal
/// simplex from the feasible point Δ = 0 (a values pass), each later one by the dual simplex
/// warm-started from the previous basis (pairs keyed by their sphere indices), on one
/// thread in a fixed order: the same pack gives the same bytes.
///
/// Multipliers: with u at an optimum strictly inside its trust box, the KKT conditions
/// read wᵢ·ŷ = Σⱼ λᵢⱼ·(−nᵢⱼ) + Σ_walls z·n_wall: the rows' multipliers λ = −y (CLP's row
/// duals y ≤ 0 on active ≤ rows) and the reduced costs z of the wall-held columns are the
/// contact forces, in m·g (the objective is in m·g per unit of u).
///
/// Frictional (`SettleOptions::friction` = μ): every sphere also has three rotation
/// columns θᵢ, and each contact within s of touching (pairs and walls) gets, instead of its
/// one non-overlap row, one row per edge Eₖ of the Coulomb pyramid (coulomb_pyramid.hpp)
/// around the normal N pushing sphere i from its partner:
///
///     Eₖ·(Δᵢ + θᵢ × (−rᵢN) − Δⱼ − θⱼ × (rⱼN)) ≥ −hᵢⱼ
///
/// (the displacement of i's contact point relative to j's along Eₖ; a wall's Δⱼ, θⱼ are 0).
/// This is the kinematics of rigid spheres with associated Coulomb sliding: a contact may
/// slip only while it opens by μ'·|slip|, so it is conservative too (the mean of the eight
/// rows is the non-overlap row), and the energy still falls monotonically. Its dual is the
/// frictional certificate's (equilibrium_certificate.hpp): at an optimum Δ = 0 the
/// multipliers βₖ ≥ 0 are forces Σₖ βₖ·Eₖ inside every pyramid that balance each sphere's
/// weight, and the rotation columns' stationarity is each sphere's torque balance. The
/// settled pack is a frictional equilibrium at μ; the certificate checks it on its own.
/// Rolling without slipping makes many moves free; each move therefore costs 10⁻⁶ of its
/// sphere's weight per unit of s (every column split into its positive and negative
/// parts), so only moves that lower the energy are taken, and the settling ends as soon as
/// the LP moves nothing.
#include <cstddef>
#include <functional>
#include <optional>
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
    /// Sliding friction μ ≥ 0 of a frictional settling; unset: frictionless.
    std::optional<double> friction;
    /// Called after every LP with the iteration count and the trust region (over d).
    std::function<void(int, double)> progress;
};

struct SettleStats {
    int iterations = 0;
    /// Ended by the trust region or by a step that moved nothing, not by the iteration
    /// bound or the solver.
    bool converged = false;
    /// Ended by a step that moved nothing (frictional: no move pays for its cost).
    bool ended_still = false;
    /// The LP solver found no feasible optimum for a step (all its starts tried): the
    /// settling stopped there, with every earlier step kept (each is overlap-free).
    bool solver_failed = false;
    double energy_drop = 0.0;  ///< Σ wᵢ·(yᵢ before − yᵢ after) / d, in m·g·d
    double move_max = 0.0;     ///< largest displacement of a sphere, over d
    double lp_seconds = 0.0;   ///< time in the LP solver (not recorded in packs)
    long long lp_pivots = 0;   ///< simplex iterations over all LPs
    /// The last LP's multipliers (frictionless only): λᵢⱼ ≥ 0 of the pair rows and the reduced
    /// costs of the columns held by a wall or the floor, the contact forces in m·g of the
    /// equilibrium found (the certificate's witness, equilibrium_certificate.hpp).
    std::vector<ContactForce> forces;
};

/// Whether this build has the LP solver (COIN-OR CLP) the settling and the certificate
/// need; without it (SGMP_WITH_CLP=OFF) both throw std::runtime_error, and `--relax` is
/// refused as a parameter.
bool lp_solver_available();

/// Settles `particles` (scale diameter `diameter`, no overlaps deeper than rounding) in
/// `container` as above. Particle order, ids, radii and colours are kept. Whether the
/// result is an equilibrium is the certificate's to say (equilibrium_certificate.hpp).
SettleStats settle_hard_spheres(std::vector<Particle>& particles, const Container& container,
                                double diameter, const SettleOptions& options = {});

}  // namespace sgmp::engine
