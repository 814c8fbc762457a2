// relax_pack (relax.hpp): the soft stage (relax.cpp), the hard-sphere finish, and the
// settling as hard spheres by sequential LP (hard_sphere_settle.hpp) or by contact dynamics
// (contact_dynamics.hpp), with their figures gathered into RelaxStats.
#include <chrono>

#include "relax_soft.hpp"
#include "sgmp/engine/contact_dynamics.hpp"
#include "sgmp/engine/hard_sphere_finish.hpp"
#include "sgmp/engine/hard_sphere_settle.hpp"
#include "sgmp/engine/relax.hpp"

namespace sgmp::engine {
namespace {

/// Contact-dynamics steps per unit of `settle_limit` (RelaxParams): the limit counts LP
/// iterations of the frictional settling and hundreds of steps of the frictionless one.
constexpr long kStepsPerSettleIteration = 100;

/// Seconds since `start`, on the steady clock (timings only: never recorded in packs).
double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The settling by contact dynamics (contact_dynamics.hpp, `--relax-settle dynamics`) from
/// the finished pack: frictionless, or at the pack's μ with --relax frictional.
void settle_by_dynamics(std::vector<Particle>& particles, const Container& container,
                        const RelaxParams& params, double diameter, RelaxStats& stats,
                        const RelaxProgressCallback& progress) {
    // Frictionless, the defaults: MPRGP with its SSOR preconditioner, first step
    // h = 0.3·√(d/g) (sgmp/engine/notes/relax-dynamics-2026-12-07.md: at N = 1002, seed 1,
    // 97 steps; with h = 0.5, 207; with h = 1 still 0.024 m·g after 1,500).
    // Frictional: NSGS contact by contact (contact_dynamics_coulomb.hpp) with inertia, each
    // step's problem in at most 5,000 sweeps, to 10⁻⁵ m·g while the pack moves and to 10⁻⁸ in
    // the polish at h/3, which goes on until every carrying contact is closed
    // (sgmp/engine/notes/relax-frictional-dynamics-2026-12-07.md: N = 150, μ = 0.5, seeds 1–24
    // all certified, 1.5× fewer sweeps than at 10⁻⁸ throughout; without inertia, or with the
    // polish down to h/27, 3–4 of 8 were).
    ContactDynamicsOptions options;
    if (params.mode == RelaxMode::Frictional) {
        options.friction = params.friction;
        options.solver = ContactSolver::Sor;
        options.relaxation = 1.0;
        options.inertia = true;
        options.sweep_tolerance = 1e-8;
        options.moving_sweep_tolerance = 1e-5;
        options.max_sweeps = 5000;
        options.smallest_step = 1.0 / 3.0;
    }
    options.max_steps = static_cast<long>(params.settle_limit) * kStepsPerSettleIteration;
    if (progress) {
        const int stages = relax_schedule(params).stages;
        options.progress = [&, stages](long step, double residual) {
            progress({RelaxProgress::Phase::Dynamics, stages - 1, stages, stats.steps,
                      static_cast<int>(step), residual});
        };
    }
    const ContactDynamicsStats settle =
        settle_by_contact_dynamics(particles, container, diameter, options);

    stats.settle_iterations = static_cast<int>(settle.steps);
    stats.settle_sweeps = settle.sweeps;
    stats.settle_converged = settle.converged;
    stats.settle_stalled = settle.stalled;
    stats.settle_returns = settle.returns;
    stats.settle_stall_returns = settle.stall_returns;
    stats.settle_closing_steps = settle.closing_steps;
    stats.settle_move_max = settle.move_max;
    stats.settle_energy_drop = settle.energy_drop;
    stats.settle_residual = settle.residual_max;
    stats.settle_forces = settle.forces;
}

}  // namespace

RelaxStats relax_pack(std::vector<Particle>& particles, const Container& container,
                      const RelaxParams& params, double diameter,
                      const RelaxProgressCallback& progress) {
    RelaxStats stats;
    if (params.mode == RelaxMode::None || particles.empty()) {
        return stats;
    }
    const auto start = std::chrono::steady_clock::now();
    relax_soft(particles, container, params, diameter, stats, progress);
    const FinishStats finish =
        finish_as_hard_spheres(particles, container, kFinishToleranceOverD * diameter);
    stats.finish_lifted = static_cast<long long>(finish.lifted);
    stats.finish_move_max = finish.move_max / diameter;
    stats.finish_move_mean = finish.move_sum / static_cast<double>(particles.size()) / diameter;
    stats.soft_seconds = seconds_since(start);
    const auto settling = std::chrono::steady_clock::now();
    if (params.settle == RelaxSettle::Dynamics) {
        settle_by_dynamics(particles, container, params, diameter, stats, progress);
        stats.settle_seconds = seconds_since(settling);
        return stats;
    }
    SettleOptions options;
    options.max_iterations = params.settle_limit;
    if (params.mode == RelaxMode::Frictional && params.friction > 0.0) {
        options.friction = params.friction;  // at μ = 0 the frictionless settling is the same
    }
    if (progress) {
        const int stages = relax_schedule(params).stages;
        options.progress = [&, stages](int iteration, double trust) {
            progress({RelaxProgress::Phase::Settling, stages - 1, stages, stats.steps, iteration,
                      trust});
        };
    }
    const SettleStats settle = settle_hard_spheres(particles, container, diameter, options);
    stats.settle_iterations = settle.iterations;
    stats.settle_converged = settle.converged;
    stats.settle_ended_still = settle.ended_still;
    stats.settle_solver_failed = settle.solver_failed;
    stats.settle_move_max = settle.move_max;
    stats.settle_energy_drop = settle.energy_drop;
    stats.settle_forces = settle.forces;
    stats.settle_seconds = seconds_since(settling);
    return stats;
}

}  // namespace sgmp::engine
