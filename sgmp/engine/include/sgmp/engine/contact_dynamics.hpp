#pragma once
/// @file contact_dynamics.hpp
/// Settles a hard-sphere pack under gravity into a frictionless mechanical equilibrium by
/// non-smooth contact dynamics: Moreau–Jean time stepping of rigid spheres with a
/// non-smooth (projected) Gauss–Seidel over the contacts, NSGS (Moreau 1988; Jean, Comput.
/// Methods Appl. Mech. Eng. 177, 235, 1999; the scheme of LMGC90 and Siconos).
///
/// Units: the pack's lengths, g = 1 (time in √(length/g)); sphere i has mass
/// mᵢ = wᵢ = (dᵢ/d)³ (d the scale diameter), so forces are in m·g. The step is
/// h = time_step·√d.
///
/// One step from positions c and kept velocities v° (below). Contacts: every pair (i, j)
/// with gap g_c = |cⱼ − cᵢ| − rᵢ − rⱼ below the reach of one step,
/// n_c = (cⱼ − cᵢ)/|cⱼ − cᵢ| (nearest image when periodic); every sphere near the floor or
/// a wall, n_c its outward normal (from the sphere into the wall):
///
///     free velocity   vᵢ* = vᵢ° − h·ŷ
///     new velocity    vᵢ⁺ = vᵢ* − (1/mᵢ)·Σ_c p_c·n_c,ᵢ      (n_c,ᵢ: the normal from i)
///     contact law     0 ≤ p_c  ⟂  g_c + h·u_c ≥ 0,   u_c = n_c·(vⱼ⁺ − vᵢ⁺)  (walls: −n_c·vᵢ⁺)
///     positions       cᵢ ← cᵢ + h·vᵢ⁺.
///
/// The goal is the static equilibrium, not the dynamics: by default every step starts at
/// rest (vᵢ° = 0). With `inertia`, a sphere keeps its velocity (vᵢ° = vᵢ⁺) while the step's
/// net force on it, Fᵢ = mᵢ·(vᵢ⁺ − vᵢ°)/h, pushes along it (Fᵢ·vᵢ⁺ > 0, FIRE's rule sphere
/// by sphere) and it does not rise (vᵢ⁺·ŷ ≤ 0), else it starts the next step at rest. Inertia
/// carries a sphere sliding or rolling down a shallow slope (a creep at a residual of
/// 10⁻² m·g, which steps from rest take h²·Rᵢ at a time), but it also keeps the motion the
/// unconverged contact problems cause: frictionless at N = 1002 (loose-random, seed 1) the
/// settling with it stalled uncertified after 223 s, without it the pack was certified
/// (sgmp/engine/notes/relax-certified-2026-12-06.md); the frictional settling needs it. With
/// inertia the polish at smaller steps (below) runs from rest, and a sphere that starts to move
/// there (a residual above `shrink_below`), or a stall at the smallest step, sends the
/// settling back to the first step, at most 5 times. With friction (`Sor`), whose steps end at
/// their sweep cap, the settling ends at rest only once every contact that carried a force is
/// closed to 0.5·10⁻⁶·d (at most 20 more polish steps, else it ends stalled). Keeping every
/// velocity, damped, pumped energy in the same way. From rest, a step is the proximal step
///
///     min Σᵢ mᵢ·|cᵢ' − cᵢ + h²·ŷ|²/2   over the linearised hard-sphere constraints.
/// The law is Signorini's at the velocity level with the gap as a
/// position correction. Since |cⱼ − cᵢ + h·(vⱼ − vᵢ)| ≥ n_c·(cⱼ − cᵢ + h·(vⱼ − vᵢ)) =
/// rᵢ + rⱼ + g_c + h·u_c, a step that keeps the law makes no overlap (walls are planes:
/// exactly). NSGS solves it one contact at a time, over-relaxed (projected SOR, ω =
/// `relaxation`),
///
///     p_c ← max(0, p_c − ω·(u_c + g_c/h)/W_c),   W_c = 1/mᵢ + 1/mⱼ   (walls: 1/mᵢ),
///
/// updating vᵢ and vⱼ at once, each sweep from the top of the pack down (the spheres are
/// ordered bottom up) — or as the dual problem min ½·pᵀWp + pᵀ(g/h + u*) over p ≥ 0
/// (W = J·M⁻¹·Jᵀ, u* the closing velocities without impulses), either by Nesterov's
/// accelerated projected gradient with gradient restart (APGD, as in Chrono; step 1/L, L a
/// Gershgorin bound on W), or, by default (`solver`), by MPRGP (Dostál, Optimal Quadratic
/// Programming Algorithms, Springer 2009, ch. 8): conjugate gradients on the contacts
/// carrying an impulse, preconditioned there by one symmetric Gauss–Seidel sweep (SSOR,
/// ω = `ssor`; 0: none), with expansion steps (a feasible step, then a projected gradient
/// step of 1.9/L) where a conjugate step would leave p ≥ 0, and proportioning steps on the
/// contacts at p = 0 that would press. Each solver starts from the last step's impulses
/// (warm start: kept per pair across neighbour-list rebuilds), and runs until no sweep or
/// iteration changes any force p_c/h by more than (MPRGP: no contact's projected gradient,
/// times m/h, exceeds)
/// `sweep_tolerance`, or `max_sweeps` (times the factor h has shrunk by, below). Displacements per
/// step are capped at `step_cap`·d (a faster sphere's velocity is scaled down; a gap that opens or
/// closes by it is corrected by the next step's g_c/h), so every pair that may touch within a step
/// is in the contact set.
///
/// Equilibrium: the impulses are h times contact forces, f_c = p_c/h, and each step's
/// momentum balance reads
///
///     Σ_c f_c·(−n_c,ᵢ) − wᵢ·ŷ = mᵢ·(vᵢ⁺ − vᵢ°)/h,
///
/// so the forces' residual on sphere i is mᵢ·|vᵢ⁺ − vᵢ°|/h, known without solving anything
/// else; Rᵢ = max(mᵢ·|vᵢ⁺ − vᵢ°|, mᵢ·|vᵢ⁺|)/h also asks the sphere to be at rest. A step with max
/// Rᵢ ≤ `residual_tolerance` divides h by `step_shrink`, so that the contact problem's tolerance
/// leaves overlaps of at most about h²·Rᵢ; the settling ends (converged) after such a step at the
/// smallest h: the spheres then move by less than residual_tolerance·h², and the forces f_c ≥ 0
/// balance every weight to that tolerance. They are returned as the certificate's witness
/// (equilibrium_certificate.hpp), which checks them on the final positions.
///
/// Step size: the unconverged part of each step's contact problem moves the spheres by
/// about h²·Rᵢ, which the next step's gaps feed back; so when the least residual of
/// `stall_window` steps is not half the least before, and that was below `shrink_below`
/// (far from an equilibrium the pack creeps on at the same h), h is divided by `step_shrink`,
/// and the sweeps per step multiplied by it, down
/// to `smallest_step`·time_step, where a stall ends the settling (not converged: the
/// certificate, with its own LP, then says whether the pack is an equilibrium).
///
/// Friction (μ = `friction` > 0): the spheres also turn, and the residual asks torques to
/// balance. The `Sor` solver then runs NSGS with an exact local Coulomb solve per contact
/// (contact_dynamics_coulomb.hpp) in the widest circular cone inside the certificate's
/// pyramid, μ·cos²(π/8) (coulomb_pyramid.hpp), so every force it finds is one the
/// frictional certificate may use; `Mprgp` solves the pyramid's 8 edge rows per contact
/// with the associated law (contact_dynamics_friction.hpp).
///
/// Everything runs in a fixed order on one thread: the same pack gives the same bytes.
#include <cstddef>
#include <functional>
#include <vector>

#include "sgmp/engine/equilibrium_certificate.hpp"
#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::engine {

/// The solver of each step's contact problem.
enum class ContactSolver {
    /// Nesterov's accelerated projected gradient on the dual, with gradient restart.
    Apgd,
    /// Projected SOR (NSGS over-relaxed), sweeps from the top down; with friction, NSGS
    /// with the closed-form Coulomb solve of each contact, alternate sweeps top down and
    /// bottom up.
    Sor,
    /// Conjugate gradients on the free contacts with expansion and proportioning steps
    /// (MPRGP: Dostál, Optimal Quadratic Programming Algorithms, Springer 2009, ch. 8),
    /// preconditioned by a symmetric Gauss–Seidel sweep when `ssor` > 0.
    Mprgp,
};

struct ContactDynamicsOptions {
    ContactSolver solver = ContactSolver::Mprgp;  ///< of each step's contact problem
    double time_step = 0.3;                       ///< first h, over √(d/g)
    double smallest_step = 1.0 / 27;              ///< smallest h, over the first
    double step_shrink = 3.0;                     ///< h is divided by this on a stall
    long stall_window = 100;                      ///< steps over which a stall is judged
    double shrink_below = 3e-3;     ///< h shrinks only once a residual was below this, m·g
    double relaxation = 1.8;        ///< ω of the projected SOR, in (0, 2)
    bool inertia = false;           ///< keep velocities while their power is positive
    double step_cap = 0.02;         ///< largest displacement per step, over d
    double sweep_tolerance = 1e-7;  ///< NSGS ends when no force changes by more, m·g
    /// With inertia: the tolerance of the steps at the first h (the pack still moving); the
    /// polish at smaller h solves to sweep_tolerance. 0: sweep_tolerance throughout.
    double moving_sweep_tolerance = 0.0;
    int max_sweeps = 500;  ///< sweeps (APGD iterations, MPRGP products) per step
    /// MPRGP only: ω of its symmetric Gauss–Seidel preconditioner, in [0, 2); 0: none.
    double ssor = 1.0;
    /// Sliding friction μ ≥ 0 of pairs and walls: above 0 every contact carries a force
    /// inside the 8-edge Coulomb pyramid (coulomb_pyramid.hpp; Sor: inside its inscribed
    /// cone), the spheres turn, and the residual asks torques to balance too (MPRGP or Sor).
    double friction = 0.0;
    double residual_tolerance = 1e-4;  ///< ends when max Rᵢ is below this, m·g
    long max_steps = 200000;           ///< steps at most
    /// Called every 100 steps with the steps so far and the largest residual (m·g).
    std::function<void(long, double)> progress;
};

struct ContactDynamicsStats {
    long steps = 0;
    long long sweeps = 0;       ///< NSGS sweeps (APGD iterations, MPRGP products), all steps
    bool converged = false;     ///< ended by the residual tolerance
    bool stalled = false;       ///< ended by a stall at the smallest step
    double residual_max = 0.0;  ///< max Rᵢ of the last step, m·g
    double time_step = 0.0;     ///< the last step's h, over √(d/g)
    std::size_t contacts = 0;   ///< contacts carrying a force at the end
    double move_max = 0.0;      ///< largest displacement of a sphere, over d
    double energy_drop = 0.0;   ///< Σ wᵢ·(yᵢ before − yᵢ after)/d, m·g·d
    int returns = 0;            ///< returns to the first step (with inertia), all causes
    int stall_returns = 0;      ///< of which after a stall at the smallest step
    int closing_steps = 0;      ///< smallest-step polish steps at rest with a carrying contact open
    /// The last step's forces f_c = p_c/h > 0, in m·g, on the caller's sphere indices.
    std::vector<ContactForce> forces;
};

/// Settles `particles` (scale diameter `diameter`; no overlaps deeper than rounding) in
/// `container` as above. Particle order, ids, radii and colours are kept; with periodic
/// sides the centres are wrapped into the cell at the end. Throws std::invalid_argument for
/// options out of range (non-finite; step, cap, tolerances or counts ≤ 0; ω outside (0, 2);
/// smallest_step outside (0, 1]; step_shrink ≤ 1; ssor outside [0, 2); friction < 0, or
/// friction with APGD).
ContactDynamicsStats settle_by_contact_dynamics(std::vector<Particle>& particles,
                                                const Container& container, double diameter,
                                                const ContactDynamicsOptions& options = {});

}  // namespace sgmp::engine
