// The soft stage of the relaxation (relax.hpp): FIRE minimisation of soft spheres under
// gravity stage by stage, a quench, and the clearing of the real spheres' overlaps.
#include "sgmp/engine/relax.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>

#include "friction.hpp"
#include "relax_soft.hpp"
#include "relax_state.hpp"
#include "sgmp/engine/neighbour_list.hpp"

namespace sgmp::engine {

namespace {

// FIRE constants (Guénolé et al. 2020, table 1) and the time-step scale (relax.hpp).
constexpr int kDelaySteps = 20;
constexpr double kDtGrow = 1.1;
constexpr double kDtShrink = 0.5;
constexpr double kAlphaStart = 0.25;
constexpr double kAlphaShrink = 0.99;
constexpr double kDtMaxTimesOmega = 0.3;
constexpr double kDtStartOverMax = 0.1;
constexpr double kDtMinOverMax = 0.002;
/// Steepest-descent steps after a last stage that did not converge.
constexpr int kQuenchSteps = 200;
/// Most steps of the clearing (clear_real_overlaps), in units of H/d_min like the stiff
/// stages' bounds (the unloading crosses the pack's height), at least kClearMinSteps; and how
/// often it checks.
constexpr double kClearCrossings = 150.0;
constexpr long kClearMinSteps = 2000;
/// Relative margin the clearing keeps between real spheres (gaps ≥ 10⁻⁹·(rᵢ + rⱼ) less the
/// finish's 10⁻¹⁰·d tolerance): touching for every contact count at δ ≥ 10⁻⁶.
constexpr double kClearMargin = 1e-9;
constexpr long kClearCheckEvery = 20;
/// Fewest steps a later stage may take (a small pack crosses its height in a few steps, but
/// FIRE needs some hundred to settle the contacts at a new stiffness).
constexpr long kMinStageSteps = 500;
/// Verlet skin over the smallest diameter.
constexpr double kSkinOverDmin = 0.25;
State make_state(const std::vector<Particle>& particles, double diameter, double shell) {
    const std::size_t n = particles.size();
    // Order by cells of side d (layer, then z, then x) so that a sphere's neighbours sit
    // near it in the arrays.
    std::vector<std::int64_t> key(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& c = particles[i].center;
        const auto cell = [&](double v) {
            return static_cast<std::int64_t>(std::floor(v / diameter));
        };
        key[i] = (cell(c.y()) * 4096 + (cell(c.z()) + 2048)) * 4096 + (cell(c.x()) + 2048);
    }
    State s;
    s.particle.resize(n);
    std::iota(s.particle.begin(), s.particle.end(), std::uint32_t{0});
    std::stable_sort(s.particle.begin(), s.particle.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    const double reference_radius = 0.5 * diameter;
    double r_min = INFINITY;
    s.spheres.reserve(n);
    s.weight.reserve(n);
    for (const std::uint32_t i : s.particle) {
        const Particle& p = particles[i];
        s.spheres.push_back(
            Ball{p.center.x(), p.center.y(), p.center.z(), p.radius * (1.0 + shell)});
        s.weight.push_back(std::pow(p.radius / reference_radius, 3));
        r_min = std::min(r_min, p.radius);
    }
    if (std::all_of(s.weight.begin(), s.weight.end(), [](double w) { return w == 1.0; })) {
        s.weight = {};  // one size: every weight is the reference m·g
    }
    s.v.assign(n, Triple{});
    s.f.assign(n, Triple{});
    s.x0.resize(n);
    s.y0.resize(n);
    s.z0.resize(n);
    s.skin = kSkinOverDmin * 2.0 * r_min;
    return s;
}

void rebuild_neighbours(State& s) {
    if (s.frictional) {
        std::swap(s.previous, s.neighbours);
    }
    s.neighbours.build(s.spheres, s.skin, s.sides);
    if (s.frictional) {
        carry_springs(s);
    }
    for (std::size_t i = 0; i < s.spheres.size(); ++i) {
        s.x0[i] = static_cast<float>(s.spheres[i].x);
        s.y0[i] = static_cast<float>(s.spheres[i].y);
        s.z0[i] = static_cast<float>(s.spheres[i].z);
    }
}

/// Magnitude of the force of a wall or the floor on a sphere crossing it by `penetration`.
inline double wall_force(double penetration, double k) {
    return penetration > 0.0 ? k * penetration : 0.0;
}

/// Adds the rolling degrees of freedom to the sums (per sphere |Fᵢ|² + |Gᵢ|²).
void add_rolling_sums(const State& s, ForceSums& sums) {
    sums.largest_squared = 0.0;
    for (std::size_t i = 0; i < s.spheres.size(); ++i) {
        const Triple &f = s.f[i], &g = s.g[i], &w = s.w[i];
        const double g2 = g.x * g.x + g.y * g.y + g.z * g.z;
        sums.force_squared += g2;
        sums.largest_squared =
            std::max(sums.largest_squared, f.x * f.x + f.y * f.y + f.z * f.z + g2);
        sums.power += g.x * w.x + g.y * w.y + g.z * w.z;
    }
}

/// Adds the normal forces of sphere i's listed pairs (partners j > i) to both spheres.
inline void add_pair_forces(State& s, double k, std::size_t i) {
    const std::vector<Ball>& p = s.spheres;
    const double xi = p[i].x, yi = p[i].y, zi = p[i].z, ri = p[i].r;
    double fxi = 0.0, fyi = 0.0, fzi = 0.0;
    for (const std::uint32_t j : s.neighbours.of(i)) {
        double dx = p[j].x - xi, dz = p[j].z - zi;
        const double dy = p[j].y - yi;
        s.sides.to_nearest_image(dx, dz);
        const double reach = ri + p[j].r;
        const double d2 = dx * dx + dy * dy + dz * dz;
        if (d2 >= reach * reach) {
            continue;
        }
        const double dist = std::sqrt(d2);
        const double f = k * (reach - dist) / dist;  // pushes j away from i
        fxi -= f * dx;
        fyi -= f * dy;
        fzi -= f * dz;
        s.f[j].x += f * dx;
        s.f[j].y += f * dy;
        s.f[j].z += f * dz;
    }
    s.f[i].x += fxi;
    s.f[i].y += fyi;
    s.f[i].z += fzi;
}

/// Adds the walls' (none with periodic sides) and the floor's normal forces to s.f[i], then
/// sphere i's terms to `sums`.
inline void add_walls_and_sum(State& s, const Container& box, double k, std::size_t i,
                              ForceSums& sums) {
    const Ball& b = s.spheres[i];
    Triple& f = s.f[i];
    if (!box.periodic) {
        f.x += wall_force(box.x_min + b.r - b.x, k) - wall_force(b.x + b.r - box.x_max, k);
        f.z += wall_force(box.z_min + b.r - b.z, k) - wall_force(b.z + b.r - box.z_max, k);
    }
    f.y += wall_force(box.floor + b.r - b.y, k);
    const double f2 = f.x * f.x + f.y * f.y + f.z * f.z;
    sums.force_squared += f2;
    sums.largest_squared = std::max(sums.largest_squared, f2);
    sums.power += f.x * s.v[i].x + f.y * s.v[i].y + f.z * s.v[i].z;
}

/// F = −∇E at the present positions (k in m·g per length unit), and the sums FIRE needs.
ForceSums compute_forces(State& s, const Container& box, double k) {
    const std::size_t n = s.spheres.size();
    for (std::size_t i = 0; i < n; ++i) {
        s.f[i].x = 0.0;
        s.f[i].y = s.gravity ? -s.weight_of(i) : 0.0;
        s.f[i].z = 0.0;
    }
    ForceSums sums;
    if (!s.frictional) {
        // Sphere i's partners come after it, so its pair forces are all in once its own
        // pairs are: the walls and the sums follow in the same pass.
        for (std::size_t i = 0; i < n; ++i) {
            add_pair_forces(s, k, i);
            add_walls_and_sum(s, box, k, i, sums);
        }
        return sums;
    }
    for (std::size_t i = 0; i < n; ++i) {
        add_pair_forces(s, k, i);
    }
    add_tangential_forces(s, box, k);
    for (std::size_t i = 0; i < n; ++i) {
        add_walls_and_sum(s, box, k, i, sums);
    }
    add_rolling_sums(s, sums);
    return sums;
}

/// v += Δt·F (and q̇ += Δt·G when frictional); returns |v|² (+ |q̇|²) after the kick.
double kick(State& s, double dt) {
    const std::size_t n = s.spheres.size();
    double v2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        s.v[i].x += dt * s.f[i].x;
        s.v[i].y += dt * s.f[i].y;
        s.v[i].z += dt * s.f[i].z;
        v2 += s.v[i].x * s.v[i].x + s.v[i].y * s.v[i].y + s.v[i].z * s.v[i].z;
    }
    for (std::size_t i = 0; i < s.w.size(); ++i) {  // rolling (frictional only)
        s.w[i].x += dt * s.g[i].x;
        s.w[i].y += dt * s.g[i].y;
        s.w[i].z += dt * s.g[i].z;
        v2 += s.w[i].x * s.w[i].x + s.w[i].y * s.w[i].y + s.w[i].z * s.w[i].z;
    }
    return v2;
}

/// FIRE's mixing v ← keep·v + steer·F, keep = 1 − α, steer = α·|v|/|F|.
struct Mixing {
    double keep = 1.0;
    double steer = 0.0;
};

/// c += step·v; rebuilds the neighbour list once a sphere may have moved skin/2. With
/// `mixing`, each velocity is mixed first, in the same pass over the spheres.
void drift(State& s, double step, std::optional<Mixing> mixing = std::nullopt) {
    std::vector<Ball>& p = s.spheres;
    double largest = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        Triple& v = s.v[i];
        if (mixing) {
            v.x = mixing->keep * v.x + mixing->steer * s.f[i].x;
            v.y = mixing->keep * v.y + mixing->steer * s.f[i].y;
            v.z = mixing->keep * v.z + mixing->steer * s.f[i].z;
        }
        p[i].x += step * v.x;
        p[i].y += step * v.y;
        p[i].z += step * v.z;
        const double dx = p[i].x - s.x0[i], dy = p[i].y - s.y0[i], dz = p[i].z - s.z0[i];
        largest = std::max(largest, dx * dx + dy * dy + dz * dz);
    }
    if (s.frictional) {  // the springs need the displacements since the last evaluation
        for (std::size_t i = 0; i < p.size(); ++i) {
            Triple& w = s.w[i];
            if (mixing) {
                w.x = mixing->keep * w.x + mixing->steer * s.g[i].x;
                w.y = mixing->keep * w.y + mixing->steer * s.g[i].y;
                w.z = mixing->keep * w.z + mixing->steer * s.g[i].z;
            }
            s.moved[i].x += step * s.v[i].x;
            s.moved[i].y += step * s.v[i].y;
            s.moved[i].z += step * s.v[i].z;
            s.rolled[i].x += step * w.x;
            s.rolled[i].y += step * w.y;
            s.rolled[i].z += step * w.z;
        }
    }
    // 1e-6 covers the float rounding of the stored positions (|c| < 10³ ⇒ error < 1e-4·skin).
    if (2.0 * std::sqrt(largest) + 1e-6 * s.skin >= s.skin) {
        rebuild_neighbours(s);
    }
}

void stop(State& s) {
    std::fill(s.v.begin(), s.v.end(), Triple{});
    std::fill(s.w.begin(), s.w.end(), Triple{});
}

struct StageResult {
    long long steps = 0;
    bool converged = false;
    double force_max = 0.0;
};

/// FIRE's adaptive step and mixing.
struct Fire {
    double dt_max;
    double dt_min;
    double dt;
    double alpha = kAlphaStart;
    long positive = 0;
    long steps = 0;
    double time = 0.0;  ///< simulated time, Σ Δt
    explicit Fire(double k)
        : dt_max(kDtMaxTimesOmega / std::sqrt(k)),
          dt_min(kDtMinOverMax * dt_max),
          dt(kDtStartOverMax * dt_max) {}

    /// One step from the forces `sums` of the present positions; returns the new ones.
    ForceSums step(State& s, const Container& box, double k, const ForceSums& sums) {
        ++steps;
        if (sums.power > 0.0) {
            if (++positive > kDelaySteps) {
                dt = std::min(dt * kDtGrow, dt_max);
                alpha *= kAlphaShrink;
            }
        } else {
            positive = 0;
            if (steps > kDelaySteps) {
                dt = std::max(dt * kDtShrink, dt_min);
                alpha = kAlphaStart;
            }
            drift(s, -0.5 * dt);
            stop(s);
        }
        const double v2 = kick(s, dt);
        const double steer =
            sums.force_squared > 0.0 ? alpha * std::sqrt(v2 / sums.force_squared) : 0.0;
        drift(s, dt, Mixing{1.0 - alpha, steer});
        time += dt;
        return compute_forces(s, box, k);
    }
};

/// Deepest overlap of a listed pair or with a wall or the floor, for radii scaled by
/// `scale` (1: the soft spheres; 1/(1 + shell): the real ones).
double deepest_overlap(const State& s, const Container& box, double scale) {
    const std::vector<Ball>& p = s.spheres;
    double deepest = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = scale * p[i].r;
        deepest = std::max(deepest, box.floor + r - p[i].y);
        if (!box.periodic) {
            deepest = std::max({deepest, box.x_min + r - p[i].x, p[i].x + r - box.x_max,
                                box.z_min + r - p[i].z, p[i].z + r - box.z_max});
        }
        for (const std::uint32_t j : s.neighbours.of(i)) {
            double dx = p[j].x - p[i].x, dz = p[j].z - p[i].z;
            const double dy = p[j].y - p[i].y;
            box.to_nearest_image(dx, dz);
            deepest =
                std::max(deepest, r + scale * p[j].r - std::sqrt(dx * dx + dy * dy + dz * dz));
        }
    }
    return deepest;
}

/// Bounds of one stage: simulated time and steps.
struct StageBound {
    double time = INFINITY;
    long steps = std::numeric_limits<long>::max();
};

/// One stiffness stage of FIRE from rest; `k` in m·g per length unit.
/// Steps between two progress calls.
constexpr long kProgressEvery = 1000;

StageResult run_stage(State& s, const Container& box, double k, const RelaxParams& params,
                      StageBound bound, const std::function<void(long)>& progress) {
    const double tolerance_squared = params.force_tolerance * params.force_tolerance;
    Fire fire(k);
    stop(s);
    ForceSums sums = compute_forces(s, box, k);
    while (sums.largest_squared > tolerance_squared && fire.steps < bound.steps &&
           fire.time < bound.time) {
        sums = fire.step(s, box, k, sums);
        if (progress && fire.steps % kProgressEvery == 0) {
            progress(fire.steps);
        }
    }
    StageResult result;
    result.steps = fire.steps;
    result.converged = sums.largest_squared <= tolerance_squared;
    result.force_max = std::sqrt(sums.largest_squared);
    return result;
}

/// Steepest descent c += η·F with η = 0.05/k (stable for up to 40 contacts of stiffness k):
/// it settles the stiff contact modes — overlaps left by spheres still moving when a stage
/// ended — at a rate of about 10 % per step, and leaves the slow modes of the pack alone.
/// Returns the largest net force left.
double quench(State& s, const Container& box, double k, int steps) {
    const double rate = 0.05 / k;
    ForceSums sums;
    for (int step = 0; step < steps; ++step) {
        sums = compute_forces(s, box, k);
        s.v = s.f;
        if (s.frictional) {
            s.w = s.g;
        }
        drift(s, rate);
    }
    stop(s);
    sums = compute_forces(s, box, k);
    return std::sqrt(sums.largest_squared);
}

/// Removes the overlaps of the real spheres (radii r/(1 + shell)) left when the stages end
/// (with shell 0 every loaded contact; a collision caught in mid-flight, a sphere pressed
/// into a wall), by FIRE on their overlap energy alone: the real spheres' contact and wall
/// forces at the last stage's stiffness, without gravity or friction. Spheres clear of the
/// others feel no force and do not move, so contacts within the shell stay as they are; the
/// overlapping spheres and the chains they press on part by about the overlaps (up to
/// 10⁻⁴·d at the bottom of a 10⁵-sphere pack) to gaps of 10⁻⁹–10⁻⁷·d (kClearMargin, then
/// FIRE's inertia). Stops once no real sphere, made kClearMargin larger, overlaps by more
/// than `tolerance` (checked every kClearCheckEvery steps), or after `max_steps`; returns
/// the steps taken. The hard-sphere finish is left nothing to resolve: pushing one sphere at a
/// time, it has to lift a sphere wedged level between its neighbours by √(2·d·δ) for an
/// overlap δ, and the spheres above it after it.
long clear_real_overlaps(State& s, const Container& box, double k, double shell, double tolerance,
                         long max_steps) {
    // The real spheres, a margin larger: they part to gaps of at least
    // kClearMargin·(rᵢ + rⱼ) − tolerance > 0, so the finish, which pushes a sphere out to
    // exactly touching one sphere at a time, never meets an overlap it would pass on up a
    // chain of touching spheres (at N = 10⁵ such pushes, each within the tolerance, added up
    // along 70 layers to lifts of 36,309 spheres).
    const double real = (1.0 + kClearMargin) / (1.0 + shell);
    if (!(deepest_overlap(s, box, real) > tolerance)) {
        return 0;
    }
    for (Ball& b : s.spheres) {
        b.r *= real;
    }
    s.gravity = false;
    const bool frictional = std::exchange(s.frictional, false);
    std::vector<Triple> rolling = std::exchange(s.w, {});  // the turns take no part
    std::vector<Triple> torques = std::exchange(s.g, {});
    Fire fire(k);
    stop(s);
    ForceSums sums = compute_forces(s, box, k);
    while (fire.steps < max_steps &&
           (fire.steps % kClearCheckEvery != 0 || deepest_overlap(s, box, 1.0) > tolerance)) {
        sums = fire.step(s, box, k, sums);
    }
    const long steps = fire.steps;
    stop(s);
    s.frictional = frictional;
    s.w = std::move(rolling);
    s.g = std::move(torques);
    s.gravity = true;
    for (Ball& b : s.spheres) {
        b.r /= real;
    }
    return steps;
}

}  // namespace

/// The soft relaxation of every stage; leaves the soft pack's positions in `particles`.
void relax_soft(std::vector<Particle>& particles, const Container& container,
                const RelaxParams& params, double diameter, RelaxStats& stats,
                const RelaxProgressCallback& progress) {
    State s = make_state(particles, diameter, params.shell);
    s.sides = container;
    rebuild_neighbours(s);
    if (params.mode == RelaxMode::Frictional) {
        enable_friction(s, params.tangential_ratio, params.friction);
    }
    double height = 0.0;
    double d_min = INFINITY;
    for (const Particle& p : particles) {
        height = std::max(height, p.center.y() + p.radius - container.floor);
        d_min = std::min(d_min, 2.0 * p.radius);
    }
    const RelaxSchedule schedule = relax_schedule(params);
    double stiffness = schedule.stiffness;
    for (int stage = 0; stage < schedule.stages; ++stage) {
        // k in m·g/d becomes k/d in m·g per length unit.
        StageBound bound;
        if (stage == 0) {
            bound.time = schedule.time * std::sqrt(height);  // g = 1
        } else {
            bound.steps = std::max(kMinStageSteps, std::lround(params.crossings * height / d_min));
        }
        std::function<void(long)> tick;
        if (progress) {
            tick = [&, stage](long steps) {
                progress({RelaxProgress::Phase::Soft, stage, schedule.stages, stats.steps + steps,
                          0, 0.0});
            };
        }
        const StageResult r = run_stage(s, container, stiffness / diameter, params, bound, tick);
        stats.steps += r.steps;
        stats.stages_converged += r.converged ? 1 : 0;
        stats.force_max = r.force_max;
        stiffness *= params.stiffness_factor;
        if (s.frictional) {  // the next stage keeps the tangential forces k_t·ξ
            scale_springs(s, 1.0 / params.stiffness_factor);
        }
    }
    if (stats.stages_converged < schedule.stages) {
        stats.force_max =
            quench(s, container, stiffness / params.stiffness_factor / diameter, kQuenchSteps);
    }
    if (progress) {
        progress({RelaxProgress::Phase::Clearing, schedule.stages - 1, schedule.stages, stats.steps,
                  0, 0.0});
    }
    stats.steps += clear_real_overlaps(
        s, container, stiffness / params.stiffness_factor / diameter, params.shell,
        kFinishToleranceOverD * diameter,
        std::max(kClearMinSteps, std::lround(kClearCrossings * height / d_min)));
    stats.overlap_max = deepest_overlap(s, container, 1.0) / diameter;  // of the soft spheres
    for (std::size_t k = 0; k < s.particle.size(); ++k) {
        particles[s.particle[k]].center =
            container.wrapped(Vec3(s.spheres[k].x, s.spheres[k].y, s.spheres[k].z));
    }
}

}  // namespace sgmp::engine
