#include "sgmp/engine/rolling.hpp"

#include "sgmp/engine/contact_search.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace sgmp::engine {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kNever = std::numeric_limits<double>::infinity();
const Vec3 kUp = Vec3::UnitY();

Vec3 center(const Sphere& s) {
    return Vec3(s.x, s.y, s.z);
}

bool same(const Sphere& a, const Sphere& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z && a.r == b.r;
}

/// A leg of the roll: p(φ) = m + ρ (cos φ·e1 + sin φ·e2), φ ≥ 0.
struct Arc {
    Vec3 m;
    double rho;
    Vec3 e1;
    Vec3 e2;
    [[nodiscard]] Vec3 at(double phi) const {
        return m + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
    }
};

/// First φ > 0 at which g(φ) = K + P cos φ + Q sin φ, allowed to be ≥ 0, turns negative
/// (0 when it is already below −tolerance or touching and approached; kNever when it never
/// does).
double entering_root(double K, double P, double Q, double tolerance) {
    const double start = K + P;
    if (start < -tolerance) {
        return 0.0;
    }
    if (start <= tolerance) {
        // Touching at the start: the contact is met at once when approached, else where g
        // falls below −tolerance/2 (a tangent start would otherwise stop every leg where it
        // begins; half the band, so that the contact made is inside it for the next leg).
        if (Q < 0.0 && (Q * 1e-6 < -tolerance || start <= -tolerance))
            return 0.0;
        K += 0.5 * tolerance;
    }
    const double R = std::hypot(P, Q);
    if (R == 0.0) {
        return kNever;
    }
    const double x = -K / R;
    if (x >= 1.0) {
        return 0.0;  // g ≤ 0 everywhere but at the start
    }
    if (x <= -1.0) {
        return kNever;  // g ≥ 0 everywhere
    }
    // g = K + R cos(φ − α) decreases through 0 at φ − α = acos(−K/R).
    double phi = std::fmod(std::atan2(Q, P) + std::acos(x), kTwoPi);
    if (phi < 0.0)
        phi += kTwoPi;
    return phi <= 1e-15 ? phi + kTwoPi : phi;
}

enum class Kind { None, Ball, Floor, Wall };

struct Hit {
    double phi = kNever;
    Kind kind = Kind::None;
    Sphere ball;
};

struct Context {
    const SettledGrid& grid;
    const Container& box;
    double r_max;
    double r;
};

/// The first new obstacle met along `arc` (current contacts excluded).
Hit first_hit(const Context& ctx, const Arc& arc, const Sphere* contacts, int count) {
    Hit hit;
    const double r = ctx.r;
    const Vec3 span = Vec3::Constant(arc.rho + r + ctx.r_max);
    ctx.grid.for_each_in_box(arc.m - span, arc.m + span, [&](const Sphere& s) {
        for (int i = 0; i < count; ++i) {
            if (same(s, contacts[i]))
                return;
        }
        const Vec3 w = arc.m - center(s);
        const double D = r + s.r;
        const double phi = entering_root(w.squaredNorm() + arc.rho * arc.rho - D * D,
                                         2.0 * arc.rho * w.dot(arc.e1),
                                         2.0 * arc.rho * w.dot(arc.e2), 1e-12 * D * D);
        if (phi < hit.phi)
            hit = Hit{phi, Kind::Ball, s};
    });
    const double tol = 1e-12 * r;
    const auto plane = [&](double K, double P, double Q, Kind kind) {
        const double phi = entering_root(K, P, Q, tol);
        if (phi < hit.phi)
            hit = Hit{phi, kind, Sphere{}};
    };
    plane(arc.m.y() - ctx.box.floor - r, arc.rho * arc.e1.y(), arc.rho * arc.e2.y(), Kind::Floor);
    if (ctx.box.periodic) {
        return hit;  // no walls
    }
    plane(ctx.box.x_max - r - arc.m.x(), -arc.rho * arc.e1.x(), -arc.rho * arc.e2.x(), Kind::Wall);
    plane(arc.m.x() - ctx.box.x_min - r, arc.rho * arc.e1.x(), arc.rho * arc.e2.x(), Kind::Wall);
    plane(ctx.box.z_max - r - arc.m.z(), -arc.rho * arc.e1.z(), -arc.rho * arc.e2.z(), Kind::Wall);
    plane(arc.m.z() - ctx.box.z_min - r, arc.rho * arc.e1.z(), arc.rho * arc.e2.z(), Kind::Wall);
    return hit;
}

/// Support coefficients of two contacts: ŷ − (ŷ·t)t = α n_j + β n_k.
std::array<double, 2> two_forces(const Vec3& nj, const Vec3& nk) {
    const double c = nj.dot(nk);
    const double det = 1.0 - c * c;
    return {(nj.y() - c * nk.y()) / det, (nk.y() - c * nj.y()) / det};
}

/// The motion of a particle at p held by `contacts` under gravity, found as the active set
/// of the frictionless contact problem: the subset A of the contacts that it keeps while
/// moving, with compressive forces on A, a downhill direction along the constraints of A,
/// and the other contacts not approached. Generically exactly one subset qualifies
/// (Gauss' principle); pairs are tried before singles. `direction` is the downhill roll
/// direction on a pair (t) or on a single support (the steepest descent).
struct Motion {
    enum class Kind { Stable, Pair, Single, Fall, Stuck } kind = Kind::Stuck;
    std::array<int, 2> keep{0, 0};
    Vec3 direction = Vec3::Zero();
};

Motion choose_motion(const Vec3& p, const Sphere* contacts, int count) {
    constexpr double kEps = 1e-12;
    std::array<Vec3, 3> n;
    for (int i = 0; i < count; ++i)
        n[i] = (p - center(contacts[i])).normalized();
    if (count == 3) {
        Eigen::Matrix3d normals;
        for (int i = 0; i < 3; ++i)
            normals.col(i) = n[i];
        const Vec3 force = normals.colPivHouseholderQr().solve(kUp);
        if (force.allFinite() && (normals * force - kUp).norm() <= 1e-9 &&
            force.minCoeff() >= -kEps) {
            return Motion{Motion::Kind::Stable, {0, 1}, Vec3::Zero()};
        }
    }
    const auto others_clear = [&](const Vec3& d, int a, int b) {
        for (int l = 0; l < count; ++l) {
            if (l != a && l != b && n[l].dot(d) < -kEps)
                return false;
        }
        return true;
    };
    for (int a = 0; a < count; ++a) {
        for (int b = a + 1; b < count; ++b) {
            if (1.0 - std::abs(n[a].dot(n[b])) < 1e-12)
                continue;
            const auto force = two_forces(n[a], n[b]);
            if (force[0] < 0.0 || force[1] < 0.0)
                continue;  // (exactly: a pair left where a force vanished stays left)
            Vec3 t = n[a].cross(n[b]).normalized();
            if (t.y() > 0.0)
                t = -t;
            // At the top of the circle (t level) either way is downhill: the rest there is
            // unstable, so the roll goes on, the way that keeps clear of the other contacts.
            for (const Vec3& d : {t, Vec3(-t)}) {
                if (d.y() <= 1e-12 && others_clear(d, a, b))
                    return Motion{Motion::Kind::Pair, {a, b}, d};
            }
        }
    }
    for (int a = 0; a < count; ++a) {
        if (n[a].y() <= 0.0)
            continue;
        Vec3 down = n[a].y() * n[a] - kUp;
        if (down.norm() < 1e-12) {
            // On top of the support: unstable, it rolls off; pick a level direction.
            down = Vec3::UnitX() - n[a].x() * n[a];
        }
        down.normalize();
        if (others_clear(down, a, a))
            return Motion{Motion::Kind::Single, {a, a}, down};
    }
    if (others_clear(-kUp, -1, -1))
        return Motion{Motion::Kind::Fall, {0, 0}, -kUp};
    return Motion{};
}

/// The rolling particle: its centre and the supports it touches (at most three).
struct Roller {
    Context ctx;
    Vec3 p;
    std::array<Sphere, 3> contacts;
    int count = 1;
};

/// A leg reached `hit` at p: the floor or a wall ends the roll, a sphere becomes a support.
std::optional<RollResult> meet(Roller& s, const Hit& hit) {
    if (hit.kind == Kind::Floor) {
        return RollResult{s.p, RollEnd::Floor};
    }
    if (hit.kind == Kind::Wall) {
        return RollResult{s.p, RollEnd::Wall};
    }
    s.contacts[s.count++] = hit.ball;
    return std::nullopt;
}

/// Keeps the supports that `motion` keeps (none for a fall); ends the roll when the
/// particle is stable or stuck.
std::optional<RollResult> keep_supports(Roller& s, const Motion& motion) {
    switch (motion.kind) {
        case Motion::Kind::Stable:
            return RollResult{s.p, RollEnd::Stable};
        case Motion::Kind::Stuck:
            return RollResult{s.p, RollEnd::Stopped};
        case Motion::Kind::Fall:
            s.count = 0;
            break;
        case Motion::Kind::Single:
            s.contacts[0] = s.contacts[motion.keep[0]];
            s.count = 1;
            break;
        case Motion::Kind::Pair: {
            const Sphere a = s.contacts[motion.keep[0]];
            const Sphere b = s.contacts[motion.keep[1]];
            s.contacts[0] = a;
            s.contacts[1] = b;
            s.count = 2;
            break;
        }
    }
    return std::nullopt;
}

/// No support: straight down to the first contact, which becomes the one support (the
/// spheres touched at the equator just left are passed, contact_search.hpp).
std::optional<RollResult> fall_leg(Roller& s) {
    constexpr double kEquatorMargin = 1e-9;
    const FirstContact hit =
        first_contact_below(s.ctx.grid, s.ctx.box, s.ctx.r_max, s.p, s.ctx.r, kEquatorMargin);
    s.p.y() = hit.y;
    if (hit.on_floor) {
        return RollResult{s.p, RollEnd::Floor};
    }
    s.contacts[0] = hit.support;
    s.count = 1;
    return std::nullopt;
}

/// Moves to `arc.at(phi)` unless the guard refuses it (then the roll stops where it is).
std::optional<RollResult> move_along(Roller& s, const Arc& arc, double phi) {
    const Vec3 next = arc.at(phi);
    if (!clear_at(s.ctx.grid, s.ctx.box, s.ctx.r_max, next, s.ctx.r)) {
        return RollResult{s.p, RollEnd::Stopped};
    }
    s.p = next;
    return std::nullopt;
}

/// One support j: down its meridian in `direction` to the first new contact, or to its
/// equator, from where the particle falls (no support left).
std::optional<RollResult> single_leg(Roller& s, const Vec3& direction) {
    const Vec3 cj = center(s.contacts[0]);
    const Arc arc{cj, s.ctx.r + s.contacts[0].r, (s.p - cj).normalized(), direction};
    const double equator = std::atan2(arc.e1.y(), -arc.e2.y());
    const Hit hit = first_hit(s.ctx, arc, s.contacts.data(), s.count);
    if (const auto end = move_along(s, arc, std::min(hit.phi, equator))) {
        return end;
    }
    if (hit.phi > equator) {
        s.count = 0;
        return std::nullopt;
    }
    return meet(s, hit);
}

/// The circle where the contact spheres of supports j and k meet, through p, rolled along
/// the downhill tangent t.
Arc pair_circle(const Roller& s, const Vec3& t) {
    const Vec3 cj = center(s.contacts[0]);
    const Vec3 axis = center(s.contacts[1]) - cj;
    const double L = axis.norm();
    const double Dj = s.ctx.r + s.contacts[0].r;
    const double Dk = s.ctx.r + s.contacts[1].r;
    const double along = (Dj * Dj - Dk * Dk + L * L) / (2.0 * L);
    const Vec3 m = cj + along * axis / L;
    const Vec3 radial = s.p - m;
    return Arc{m, radial.norm(), radial.normalized(), t};
}

/// Where on [0, phi] a support force of the pair first vanishes (just past it, by
/// bisection to 60 halvings), or phi when both stay compressive to the end.
double force_vanishes(const Roller& s, const Arc& arc, double phi, bool& vanishes) {
    const Vec3 cj = center(s.contacts[0]);
    const Vec3 ck = center(s.contacts[1]);
    const auto pulls = [&](double angle) {
        const Vec3 q = arc.at(angle);
        const auto f = two_forces((q - cj).normalized(), (q - ck).normalized());
        return f[0] < 0.0 || f[1] < 0.0;
    };
    vanishes = pulls(phi);
    if (!vanishes) {
        return phi;
    }
    double lo = 0.0;
    double hi = phi;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (pulls(mid) ? hi : lo) = mid;
    }
    return hi;
}

/// Two supports: along their circle to the first new contact, to the circle's lowest
/// point, or to where a support force vanishes (then the next leg goes on with the other).
std::optional<RollResult> pair_leg(Roller& s, const Vec3& direction) {
    const Arc arc = pair_circle(s, direction);
    double lowest = std::atan2(arc.e2.y(), arc.e1.y()) + std::numbers::pi;
    if (lowest <= 0.0)
        lowest += kTwoPi;
    const Hit hit = first_hit(s.ctx, arc, s.contacts.data(), s.count);
    bool leaves = false;
    const double phi = force_vanishes(s, arc, std::min(hit.phi, lowest), leaves);
    if (const auto end = move_along(s, arc, phi)) {
        return end;
    }
    if (!leaves && hit.phi <= lowest) {
        return meet(s, hit);
    }
    return std::nullopt;
}

}  // namespace

RollResult roll_to_rest(const SettledGrid& grid, const Container& container, double r_max,
                        const Vec3& start, double r, const Sphere& support) {
    Roller s{Context{grid, container, r_max, r}, start, {support, Sphere{}, Sphere{}}, 1};
    constexpr int kMaxLegs = 1000;
    for (int leg = 0; leg < kMaxLegs; ++leg) {
        Motion motion;
        if (s.count > 0) {
            motion = choose_motion(s.p, s.contacts.data(), s.count);
            if (const auto end = keep_supports(s, motion)) {
                return *end;
            }
        }
        const auto end = s.count == 0   ? fall_leg(s)
                         : s.count == 1 ? single_leg(s, motion.direction)
                                        : pair_leg(s, motion.direction);
        if (end) {
            return *end;
        }
    }
    return RollResult{s.p, RollEnd::Stopped};
}

}  // namespace sgmp::engine
