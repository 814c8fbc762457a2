#include "sgmp/engine/contact_dynamics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "contact_dynamics_coulomb.hpp"
#include "contact_dynamics_friction.hpp"
#include "contact_dynamics_solvers.hpp"
#include "contact_dynamics_state.hpp"
#include "sgmp/engine/coulomb_pyramid.hpp"
#include "sgmp/engine/neighbour_list.hpp"

namespace sgmp::engine {

namespace {

using namespace contact_dynamics;
constexpr long kProgressEvery = 100;
/// Returns to the first step after a sphere moved in the polish (with inertia), at most.
constexpr int kMostReturns = 5;

/// The widest gap, over d, at which a carrying contact counts as closed when a frictional
/// NSGS settling ends: half the certificate's contact tolerance (10⁻⁶).
constexpr double kClosedGapOverD = 0.5e-6;

/// Polish steps at rest that may close the carrying contacts before the settling ends.
constexpr int kMostOpenPolish = 20;

/// Verlet skin over the smallest diameter (as the soft stage's).
constexpr double kSkinOverDmin = 0.25;
void check_options(const ContactDynamicsOptions& o) {
    const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
    if (!positive(o.time_step) || !positive(o.step_cap) || !positive(o.sweep_tolerance) ||
        !positive(o.residual_tolerance) || !positive(o.smallest_step) || o.smallest_step > 1.0 ||
        !(std::isfinite(o.step_shrink) && o.step_shrink > 1.0) || !positive(o.relaxation) ||
        !positive(o.shrink_below) || o.relaxation >= 2.0 || o.max_sweeps < 1 || o.max_steps < 1 ||
        o.stall_window < 1 || !(o.ssor >= 0.0 && o.ssor < 2.0) ||
        !(std::isfinite(o.friction) && o.friction >= 0.0) ||
        !(std::isfinite(o.moving_sweep_tolerance) && o.moving_sweep_tolerance >= 0.0) ||
        (o.friction > 0.0 && o.solver == ContactSolver::Apgd)) {
        throw std::invalid_argument(
            "contact dynamics: steps, cap and tolerances must be finite and > 0, relaxation in "
            "(0, 2), smallest step in (0, 1], shrink > 1, sweeps, steps and window >= 1, ssor in "
            "[0, 2), friction and the moving sweeps' tolerance finite and >= 0 (with friction: "
            "the MPRGP or SOR solver)");
    }
}

Dynamics make_dynamics(const std::vector<Particle>& particles, const Container& box,
                       double diameter, const ContactDynamicsOptions& o) {
    const std::size_t n = particles.size();
    std::vector<std::int64_t> key(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& c = particles[i].center;
        const auto cell = [&](double x) {
            return static_cast<std::int64_t>(std::floor(x / diameter));
        };
        key[i] = (cell(c.y()) * 4096 + (cell(c.z()) + 2048)) * 4096 + (cell(c.x()) + 2048);
    }
    Dynamics s;
    s.particle.resize(n);
    std::iota(s.particle.begin(), s.particle.end(), std::uint32_t{0});
    std::stable_sort(s.particle.begin(), s.particle.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    double r_min = INFINITY;
    for (const std::uint32_t i : s.particle) {
        const Particle& p = particles[i];
        s.balls.push_back(Ball{p.center.x(), p.center.y(), p.center.z(), p.radius});
        s.inv_m.push_back(1.0 / std::pow(2.0 * p.radius / diameter, 3));
        r_min = std::min(r_min, p.radius);
    }
    s.v.assign(n, V3{});
    s.kept.assign(n, V3{});
    s.wall_p.assign(5 * n, 0.0);
    s.box = box;
    s.h = o.time_step * std::sqrt(diameter);
    s.skin = kSkinOverDmin * 2.0 * r_min;
    s.cap = std::min(o.step_cap * diameter, s.skin / 8.0);
    s.diameter = diameter;
    if (o.friction > 0.0) {
        if (o.solver == ContactSolver::Sor) {  // NSGS: the cone inside the certificate's pyramid
            prepare_friction(s, pyramid_inscribed_friction(o.friction), 3);
        } else {
            prepare_friction(s, o.friction, kPyramidEdges);
        }
    }
    return s;
}

/// Rebuilds the neighbour list and carries each pair's impulse over to its new slot.
void rebuild(Dynamics& s) {
    std::swap(s.previous, s.list);
    s.list.build(s.balls, s.skin, s.box);
    const std::size_t m = s.stride;  // impulses kept per slot
    std::vector<double> next(s.list.pairs() * m, 0.0);
    if (!s.pair_p.empty()) {
        for (std::size_t i = 0; i < s.balls.size(); ++i) {
            const auto old = s.previous.of(i);
            const auto now = s.list.of(i);
            for (std::size_t k = 0; k < old.size(); ++k) {
                const auto from = s.pair_p.begin() +
                                  static_cast<std::ptrdiff_t>((s.previous.first_slot(i) + k) * m);
                const bool pressed = std::any_of(from, from + static_cast<std::ptrdiff_t>(m),
                                                 [](double p) { return p != 0.0; });
                const auto at = pressed ? std::find(now.begin(), now.end(), old[k]) : now.end();
                if (at != now.end()) {
                    const std::size_t to =
                        (s.list.first_slot(i) + static_cast<std::size_t>(at - now.begin())) * m;
                    std::copy(from, from + static_cast<std::ptrdiff_t>(m),
                              next.begin() + static_cast<std::ptrdiff_t>(to));
                }
            }
        }
    }
    s.pair_p.swap(next);
    s.at_build.resize(s.balls.size());
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
        s.at_build[i] = V3{s.balls[i].x, s.balls[i].y, s.balls[i].z};
    }
}

/// Rebuilds the list once a sphere may have moved so far since the last build that an
/// unlisted pair could close within a step: 2·moved > skin − 2·cap.
void keep_list(Dynamics& s) {
    double largest = 0.0;
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
        const double dx = s.balls[i].x - s.at_build[i].x, dy = s.balls[i].y - s.at_build[i].y,
                     dz = s.balls[i].z - s.at_build[i].z;
        largest = std::max(largest, dx * dx + dy * dy + dz * dz);
    }
    if (2.0 * std::sqrt(largest) >= s.skin - 2.0 * s.cap) {
        rebuild(s);
    }
}

/// The separation cⱼ − cᵢ of spheres i and j (nearest image when periodic) and its length.
struct Separation {
    double dx = 0.0;
    double dy = 0.0;
    double dz = 0.0;
    double dist = 0.0;
};

Separation separation(const Dynamics& s, std::size_t i, std::size_t j) {
    const std::vector<Ball>& b = s.balls;
    double dx = b[j].x - b[i].x, dz = b[j].z - b[i].z;
    const double dy = b[j].y - b[i].y;
    s.box.to_nearest_image(dx, dz);
    return {dx, dy, dz, std::sqrt(dx * dx + dy * dy + dz * dz)};
}

/// The step's contacts: listed pairs and walls whose gap one step may close (< 2·cap), with
/// the last step's impulses.
void gather_contacts(Dynamics& s) {
    s.contacts.clear();
    const double reach = 2.0 * s.cap;
    const std::vector<Ball>& b = s.balls;
    for (std::size_t i = 0; i < b.size(); ++i) {
        const std::size_t first = s.list.first_slot(i);
        const auto near = s.list.of(i);
        for (std::size_t k = 0; k < near.size(); ++k) {
            const std::uint32_t j = near[k];
            const auto [dx, dy, dz, dist] = separation(s, i, j);
            const double gap = dist - b[i].r - b[j].r;
            if (gap >= reach) {
                continue;
            }
            const auto slot = static_cast<std::uint32_t>(first + k);
            s.contacts.push_back(Contact{static_cast<std::uint32_t>(i), j, dx / dist, dy / dist,
                                         dz / dist, gap, 1.0 / (s.inv_m[i] + s.inv_m[j]),
                                         s.pair_p[slot], slot, 0});
        }
        const Vec3 c(b[i].x, b[i].y, b[i].z);
        const std::array<WallGap, 5> walls = wall_gaps(c, b[i].r, s.box);
        for (std::uint32_t w = 0; w < 5; ++w) {
            if (walls[w].gap < reach) {
                const Vec3& n = walls[w].normal;  // inward: the contact's normal is −n
                const auto slot = static_cast<std::uint32_t>(5 * i + w);
                s.contacts.push_back(Contact{static_cast<std::uint32_t>(i), kWall, -n.x(), -n.y(),
                                             -n.z(), walls[w].gap, 1.0 / s.inv_m[i], s.wall_p[slot],
                                             slot, w});
            }
        }
    }
}

/// v ← −h·ŷ (each step starts at rest), then the warm-start impulses.
void start_velocities(Dynamics& s) {
    for (std::size_t i = 0; i < s.v.size(); ++i) {
        s.v[i] = V3{s.kept[i].x, s.kept[i].y - s.h, s.kept[i].z};
    }
    for (const Contact& c : s.contacts) {
        if (c.p > 0.0) {
            apply(s, c, c.p);
        }
    }
}

/// Keeps the impulses for the next step's warm start (a pair or wall not in the step's
/// contacts is open: 0).
void store_impulses(Dynamics& s) {
    std::fill(s.pair_p.begin(), s.pair_p.end(), 0.0);
    std::fill(s.wall_p.begin(), s.wall_p.end(), 0.0);
    for (const Contact& c : s.contacts) {
        kept_impulses(s, c.b)[c.slot] = c.p;
    }
}

/// The largest residual mᵢ·|vᵢ⁺|/h of the step (it started at rest), in m·g.
double step_residual(const Dynamics& s) {
    double largest = 0.0;
    for (std::size_t i = 0; i < s.v.size(); ++i) {
        const V3& v = s.v[i];
        const V3& k = s.kept[i];
        const double dx = v.x - k.x, dy = v.y - k.y, dz = v.z - k.z;
        const double r2 = std::max(v.x * v.x + v.y * v.y + v.z * v.z, dx * dx + dy * dy + dz * dz);
        largest = std::max(largest, std::sqrt(r2) / s.inv_m[i]);
    }
    return largest / s.h;
}

/// Keeps a sphere's velocity for the next step while the net force on it pushes along it
/// (power F·v > 0, F = m·(v⁺ − v_kept)/h), else stops it (FIRE's rule, sphere by sphere).
void keep_velocities(Dynamics& s, bool inertia) {
    for (std::size_t i = 0; i < s.v.size(); ++i) {
        const V3& v = s.v[i];
        V3& k = s.kept[i];
        const double power = (v.x - k.x) * v.x + (v.y - k.y) * v.y + (v.z - k.z) * v.z;
        k = inertia && power > 0.0 && v.y <= 0.0 ? v : V3{};
    }
}

/// c ← c + h·v, each displacement capped at `cap` (the velocity scaled down).
void move(Dynamics& s) {
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
        V3& v = s.v[i];
        const double step = s.h * std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        if (step > s.cap) {
            const double scale = s.cap / step;
            v = V3{scale * v.x, scale * v.y, scale * v.z};
        }
        s.balls[i].x += s.h * v.x;
        s.balls[i].y += s.h * v.y;
        s.balls[i].z += s.h * v.z;
    }
}

/// The last step's forces p/h > 0 on the caller's indices; with NSGS friction, also the
/// tangential force on `first` (the impulse vector P is on b, −P on a).
std::vector<ContactForce> contact_forces(const Dynamics& s) {
    static constexpr std::array<Partner, 5> kWalls{Partner::Floor, Partner::XMin, Partner::XMax,
                                                   Partner::ZMin, Partner::ZMax};
    const bool vectors = s.impulse.size() == s.contacts.size();
    std::vector<ContactForce> forces;
    for (std::size_t k = 0; k < s.contacts.size(); ++k) {
        const Contact& c = s.contacts[k];
        if (c.p <= 0.0) {
            continue;
        }
        ContactForce f;
        f.first = s.particle[c.a];
        if (c.b == kWall) {
            f.partner = kWalls[c.wall];
        } else {
            f.second = s.particle[c.b];
        }
        f.force = c.p / s.h;
        if (vectors) {
            const V3& p = s.impulse[k];
            const Vec3 n(c.nx, c.ny, c.nz);
            const Vec3 on_b(p.x, p.y, p.z);
            f.tangential = -(on_b - on_b.dot(n) * n) / s.h;
        }
        forces.push_back(f);
    }
    return forces;
}

/// The widest gap, over d, of a contact that carried a force in the last step, at the
/// positions after it (pairs by nearest image, walls and floor).
double carrying_gap_max(const Dynamics& s) {
    double widest = 0.0;
    const std::vector<Ball>& b = s.balls;
    for (const Contact& c : s.contacts) {
        if (c.p <= 0.0) {
            continue;
        }
        double gap = 0.0;
        if (c.b == kWall) {
            const Vec3 centre(b[c.a].x, b[c.a].y, b[c.a].z);
            gap = wall_gaps(centre, b[c.a].r, s.box)[c.wall].gap;
        } else {
            gap = separation(s, c.a, c.b).dist - b[c.a].r - b[c.b].r;
        }
        widest = std::max(widest, gap);
    }
    return widest / s.diameter;
}

/// Writes the positions back (wrapped when periodic) and fills the move and energy figures.
void write_back(const Dynamics& s, std::vector<Particle>& particles, double diameter,
                ContactDynamicsStats& stats) {
    for (std::size_t k = 0; k < s.particle.size(); ++k) {
        Particle& p = particles[s.particle[k]];
        const Vec3 c(s.balls[k].x, s.balls[k].y, s.balls[k].z);
        stats.move_max = std::max(stats.move_max, (c - p.center).norm() / diameter);
        stats.energy_drop += (p.center.y() - c.y()) / (s.inv_m[k] * diameter);
        p.center = s.box.wrapped(c);
    }
}

/// Divides the step by `factor`, and the kept impulses with it (the forces p/h stay).
void shrink_step(Dynamics& s, double factor) {
    s.h /= factor;
    std::fill(s.kept.begin(), s.kept.end(), V3{});  // the polish starts at rest
    for (double& p : s.pair_p) {
        p /= factor;
    }
    for (double& p : s.wall_p) {
        p /= factor;
    }
}

/// The frictional contact problem of a step: contact by contact (Sor) or over the pyramid's
/// edge rows (MPRGP); returns the step's residual, m·g.
double solve_frictional(Dynamics& s, const ContactDynamicsOptions& o, int sweeps,
                        ContactDynamicsStats& stats) {
    if (o.solver == ContactSolver::Sor) {
        gather_coulomb(s);
        start_coulomb_velocities(s);
        stats.sweeps += solve_coulomb(s, o.sweep_tolerance, o.relaxation, sweeps);
        store_coulomb_impulses(s);
    } else {
        gather_edges(s);
        start_edge_velocities(s);
        stats.sweeps += solve_edges(s, o.sweep_tolerance, sweeps, o.ssor);
        store_edge_impulses(s);
    }
    return edge_step_residual(s);
}

/// The frictionless contact problem of a step; returns the step's residual, m·g.
double solve_frictionless(Dynamics& s, const ContactDynamicsOptions& o, int sweeps,
                          ContactDynamicsStats& stats) {
    start_velocities(s);
    switch (o.solver) {
        case ContactSolver::Apgd:
            stats.sweeps += solve_apgd(s, o.sweep_tolerance, sweeps);
            break;
        case ContactSolver::Sor:
            stats.sweeps += solve_sor(s, o.sweep_tolerance, o.relaxation, sweeps);
            break;
        case ContactSolver::Mprgp:
            stats.sweeps += solve_normal_mprgp(s, o.sweep_tolerance, sweeps, o.ssor);
            break;
    }
    store_impulses(s);
    return step_residual(s);
}

/// One time step; returns its largest residual, m·g.
double step(Dynamics& s, const ContactDynamicsOptions& o, int sweeps, ContactDynamicsStats& stats) {
    keep_list(s);
    gather_contacts(s);
    const double residual = s.friction > 0.0 ? solve_frictional(s, o, sweeps, stats)
                                             : solve_frictionless(s, o, sweeps, stats);
    move(s);
    keep_velocities(s, o.inertia);
    ++stats.steps;
    return residual;
}

}  // namespace

ContactDynamicsStats settle_by_contact_dynamics(std::vector<Particle>& particles,
                                                const Container& container, double diameter,
                                                const ContactDynamicsOptions& options) {
    check_options(options);
    if (!(diameter > 0.0) || !std::isfinite(diameter)) {
        throw std::invalid_argument("contact dynamics: diameter must be finite and > 0");
    }
    ContactDynamicsStats stats;
    if (particles.empty()) {
        stats.converged = true;
        return stats;
    }
    Dynamics s = make_dynamics(particles, container, diameter, options);
    rebuild(s);
    const double h_first = options.time_step * std::sqrt(diameter);
    const double h_min = options.time_step * options.smallest_step * std::sqrt(diameter);
    double best_before = INFINITY;  // the least residual before the present window
    double best = INFINITY;
    // With inertia, the polish at smaller steps starts and stays at rest; a sphere that
    // starts to move there (a residual above shrink_below) sends the settling back to the
    // first step, with inertia, at most kMostReturns times.
    ContactDynamicsOptions live = options;
    // With inertia, the steps at h₀ solve to the moving tolerance, the polish to the tight one.
    const auto set_moving = [&](bool moving) {
        live.inertia = moving;
        live.sweep_tolerance = moving && options.moving_sweep_tolerance > 0.0
                                   ? options.moving_sweep_tolerance
                                   : options.sweep_tolerance;
    };
    set_moving(options.inertia);
    int returns = 0;
    // Back to the first step with inertia, at most kMostReturns times; false when none is left.
    const auto back_to_first_step = [&] {
        if (!options.inertia || returns >= kMostReturns) {
            return false;
        }
        shrink_step(s, s.h / h_first);
        set_moving(true);
        ++returns;
        stats.returns = returns;
        best_before = best = INFINITY;
        return true;
    };
    const auto polish = [&] {  // the next smaller step, from rest
        shrink_step(s, std::min(options.step_shrink, s.h / h_min));
        set_moving(false);
    };
    int open_polish = 0;  // polish steps at rest with a carrying contact still open
    while (stats.steps < options.max_steps) {
        // Each shrink of h multiplies the sweeps by the same factor: the smaller steps are
        // there to converge the contact problem, not to move.
        const double ratio = std::round(options.time_step * std::sqrt(diameter) / s.h);
        const int sweeps = static_cast<int>(std::min(1e8, options.max_sweeps * ratio));
        stats.residual_max = step(s, live, sweeps, stats);
        best = std::min(best, stats.residual_max);
        const bool smallest = s.h <= h_min * (1.0 + 1e-12);
        if (stats.residual_max <= options.residual_tolerance) {
            // Frictional NSGS steps end at their sweep cap, unconverged: at rest, a contact
            // may still carry a force across a gap the certificate would not count as a
            // contact; the polish goes on until every carrying contact is closed.
            const bool closed = s.friction == 0.0 || options.solver != ContactSolver::Sor ||
                                carrying_gap_max(s) <= kClosedGapOverD;
            if (smallest && closed) {
                stats.converged = true;
                break;
            }
            if (smallest && ++open_polish < kMostOpenPolish) {
                stats.closing_steps = open_polish;
                continue;
            }
            if (smallest) {
                stats.stalled = true;  // the certificate says whether the pack is one
                break;
            }
            polish();  // the gaps
            continue;
        }
        if (!live.inertia && stats.residual_max > options.shrink_below && back_to_first_step()) {
            continue;  // a sphere moved in the polish
        }
        if (stats.steps % options.stall_window == 0) {
            // Stalled near an equilibrium (a creep far from one goes on at the same h; with
            // inertia, a sphere still gathering speed is not a stall): smaller steps, or the
            // end.
            const bool moving = live.inertia && stats.residual_max > 2.0 * best;
            if (best > 0.5 * best_before && best_before < options.shrink_below && !moving) {
                if (smallest && back_to_first_step()) {
                    ++stats.stall_returns;
                    continue;  // a creep the polish cannot end
                }
                if (smallest) {
                    stats.stalled = true;
                    break;
                }
                polish();
            }
            best_before = std::min(best_before, best);
            best = INFINITY;
        }
        if (options.progress && stats.steps % kProgressEvery == 0) {
            options.progress(stats.steps, stats.residual_max);
        }
    }
    stats.time_step = s.h / std::sqrt(diameter);
    stats.forces = contact_forces(s);
    stats.contacts = stats.forces.size();
    write_back(s, particles, diameter, stats);
    return stats;
}

}  // namespace sgmp::engine
