#pragma once
/// @file relax.hpp
/// Collective relaxation of a deposited pack (`--relax frictionless`): the whole pack slides
/// under gravity into a mechanical equilibrium of frictionless spheres in the container, then
/// is finished as hard spheres (hard_sphere_finish.hpp).
///
/// Soft model. With m the mass and d the diameter of a sphere of relative size 1, g gravity,
/// wᵢ = (dᵢ/d)³ the weight of sphere i in units of m·g, the soft radii aᵢ = (1 + s)·rᵢ (s the
/// contact shell), δᵢⱼ = max(0, aᵢ + aⱼ − |cᵢ − cⱼ|) the soft overlap of a pair and
/// δᵢ^wall = max(0, aᵢ − distance of cᵢ from a wall or the floor):
///
///     E(c) / (m·g·d) = Σᵢ wᵢ·yᵢ/d + (k/2)·Σ_pairs (δᵢⱼ/d)² + (k/2)·Σᵢ Σ_walls (δᵢ^wall/d)²
///
/// with the stiffness k in m·g/d (a contact carrying one weight overlaps by d/k). The force
/// Fᵢ = −∇ᵢE has no tangential part: the spheres are frictionless. A minimum of E with every
/// |Fᵢ| ≤ tolerance·m·g is a mechanical equilibrium of the soft pack.
///
/// Minimiser: FIRE (Bitzek et al., PRL 97, 170201, 2006) in the form of Guénolé et al.
/// (Comput. Mater. Sci. 175, 109584, 2020): semi-implicit Euler steps of unit-mass dynamics
/// v += Δt·F, v ← (1 − α)·v + α·|v|·F/|F|, c += Δt·v, with Δt grown by 1.1 and α shrunk by
/// 0.99 after 20 steps of positive power P = F·v, and on P ≤ 0 a half step back, v = 0,
/// Δt halved, α reset to 0.25. The time step is set by the contact frequency
/// ω = √(k·g/d): Δt_max = 0.3/ω, Δt starts at Δt_max/10 and never falls below Δt_max/500.
/// Equal inertia for every sphere is a choice of the minimiser; it changes the path, not
/// the equilibrium. Neighbours come from a Verlet list (neighbour_list.hpp, skin 0.25·d_min).
///
/// Stiffness schedule: stages s = 0 … stages−1 at k_s = k₀·factorˢ, each started at rest from
/// the previous one's end and run until max|Fᵢ| ≤ tolerance or its bound (each mode's
/// defaults: relax_schedule in relax_params.hpp). The soft first stage does the collective
/// rearrangement with long time steps; it is bounded in simulated time, `time`·√(H/g) (H
/// the pack's height above the floor), since the collapse takes about a free fall through
/// the pack. Frictionless, by default, that one stage (k₀ = 2·10⁴: overlaps of about
/// 5·10⁻⁴·d at N = 3000) runs to convergence, so the hard-sphere settling starts from a soft
/// equilibrium. Frictional, by default, it is softer (k₀ = 2·10³, overlaps of about 0.5 %
/// of d, like the DEM reference's Hertz contacts) and bounded at 5·√(H/g), and four
/// stiffer stages (ending at 2·10⁷) squeeze the overlaps below the shell; that is an
/// elastic relaxation across the pack's height, so they are bounded by `crossings`·H/d_min
/// steps (at least 500), whatever k. When a stage ends unconverged, 200 steps of steepest
/// descent c += (0.05/k)·F settle the stiff contact modes (overlaps of spheres still moving)
/// without moving the slow modes. Then the real spheres' overlaps (the loaded contacts; a
/// collision caught in mid-flight, a sphere pressed into a wall) are removed by FIRE on
/// their overlap energy alone, without gravity — the clearing: only the overlapping spheres
/// and the chains they press on move, by about the overlaps (up to 10⁻⁴·d), so the pack
/// unloads elastically, its contacts end touching, and the finish starts clean (about 400
/// steps at N = 3000–9000).
///
/// Frictionless packs under gravity creep (reference/README.md: a μ = 0 DEM pour takes 7×
/// the steps of a μ = 0.01 one): the frictionless stage at 2·10⁴ converges in 6·10⁴–1.5·10⁵
/// steps at N = 1000–3000. The frictional stages' bounds usually end them before the
/// tolerance is met; `relax_force_max` in the header says what is left.
///
/// Settle: the hard-sphere pack is then settled under gravity into an exact equilibrium by
/// sequential linear programming (hard_sphere_settle.hpp), frictionless or frictional at
/// the relaxation's μ (at μ = 0 the frictionless settling); with `settle` =
/// RelaxSettle::Dynamics (`--relax-settle dynamics`, frictionless only) by non-smooth
/// contact dynamics instead (contact_dynamics.hpp: Moreau–Jean steps, each step's contact
/// problem by SSOR-preconditioned MPRGP), whose contact forces are offered to the certificate as
/// its witness. The pack's certificate checks either (equilibrium_certificate.hpp).
///
/// Finish: the real spheres are (1 + s) times smaller than the soft ones (default s = 0: the
/// same), so a soft overlap below s·(rᵢ + rⱼ) is a real gap of at most s·(rᵢ + rⱼ); deeper
/// ones — with s = 0 every loaded contact — are parted by the clearing, and whatever is left
/// is removed by the hard-sphere finish (hard_sphere_finish.hpp).
///
/// Frictional (`--relax frictional`): the same, with a Coulomb-limited tangential spring at
/// every contact and three rolling degrees of freedom per sphere in the FIRE vectors
/// (src/friction.hpp); each new stage divides the springs by the stiffness factor, so the
/// tangential forces carry over.
///
/// Everything runs in a fixed order on one thread, so the same pack gives the same bytes.
#include <cstddef>
#include <functional>
#include <vector>

#include "sgmp/engine/equilibrium_certificate.hpp"
#include "sgmp/engine/relax_params.hpp"
#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::engine {

/// What the relaxation did (also recorded in the pack's metadata).
struct RelaxStats {
    long long steps = 0;            ///< minimiser steps over all stages
    int stages_converged = 0;       ///< stages that reached the force tolerance
    double force_max = 0.0;         ///< largest net force on a sphere at the end, in m·g
    double overlap_max = 0.0;       ///< deepest soft overlap at the end (pairs, walls), over d
    long long finish_lifted = 0;    ///< spheres the finish had to lift straight up
    double finish_move_max = 0.0;   ///< largest displacement by the hard-sphere finish, over d
    double finish_move_mean = 0.0;  ///< mean displacement by the hard-sphere finish, over d
    /// LP iterations (frictional) or contact-dynamics steps (frictionless) of the settling.
    int settle_iterations = 0;
    bool settle_converged = false;      ///< the settling ended by its trust region or stillness
    bool settle_ended_still = false;    ///< the settling's last step moved nothing
    bool settle_solver_failed = false;  ///< the settling's LP solver failed; it stopped there
    double settle_move_max = 0.0;       ///< largest displacement by the settling, over d
    double settle_energy_drop = 0.0;    ///< potential energy the settling released, m·g·d
    /// The settling's contact forces, offered to the certificate as its witness (not
    /// recorded in packs).
    std::vector<ContactForce> settle_forces;
    bool settle_stalled = false;   ///< the contact dynamics stalled at its smallest step
    long long settle_sweeps = 0;   ///< products with W of the contact dynamics (frictionless)
    int settle_returns = 0;        ///< the contact dynamics' returns to its first step
    int settle_stall_returns = 0;  ///< of which after a stall at the smallest step
    int settle_closing_steps = 0;  ///< its polish steps with a carrying contact still open
    double settle_residual = 0.0;  ///< largest force residual of its last step, m·g
    double soft_seconds = 0.0;     ///< wall clock of the soft stages and the finish (not recorded)
    double settle_seconds = 0.0;   ///< wall clock of the settling (not recorded)
};

/// Where a running relaxation is, for progress lines (it changes no result).
struct RelaxProgress {
    /// Settling: the frictional LP settling; Dynamics: the frictionless contact dynamics.
    enum class Phase { Soft, Clearing, Settling, Dynamics };
    Phase phase = Phase::Soft;
    int stage = 0;              ///< soft stage, from 0
    int stages = 0;             ///< soft stages in all
    long long steps = 0;        ///< minimiser steps so far, over all soft stages
    int settle_iteration = 0;   ///< LP iterations (Dynamics: time steps) of the settling so far
    double settle_trust = 0.0;  ///< its trust region, over d (Dynamics: largest residual, m·g)
};
using RelaxProgressCallback = std::function<void(const RelaxProgress&)>;

/// Relaxes `particles` (of scale diameter `diameter`) in `container` as described above and
/// finishes them as hard spheres: afterwards no pair overlaps and every sphere is inside the
/// container. Does nothing for `RelaxMode::None`. Particle order, ids, radii and colours are
/// kept. `progress`, when given, is called every 1000 minimiser steps, as the clearing
/// starts and after every LP of the settling.
RelaxStats relax_pack(std::vector<Particle>& particles, const Container& container,
                      const RelaxParams& params, double diameter,
                      const RelaxProgressCallback& progress = {});

}  // namespace sgmp::engine
