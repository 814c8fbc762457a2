#include "sgmp/engine/contact_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sgmp/engine/contact_search.hpp"
#include "sgmp/engine/rolling.hpp"

namespace sgmp::engine {

namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

/// Smallest angle ≥ from (up to rounding) congruent to `angle` modulo 2π.
double next_angle_after(double angle, double from) {
    const double turn = 2.0 * std::numbers::pi;
    return angle + turn * std::ceil((from - angle) / turn - 1e-12);
}

/// The outcome of `roll_to_rest` in the protocol's terms.
DropOutcome outcome_of(const RollResult& rolled, StopReason reason, long moves) {
    switch (rolled.end) {
        case RollEnd::Floor:
            return DropOutcome{rolled.center, StopReason::Floor, moves};
        case RollEnd::Wall:
            return DropOutcome{rolled.center, StopReason::Wall, moves};
        default:
            return DropOutcome{rolled.center, reason, moves};
    }
}

/// The support's meridian (see roll_over_support): u, D and the angle range.
struct Meridian {
    Vec3 cj;
    Vec3 u;
    double D;
    double phi0;
};

/// First φ ≥ φ0 where the meridian meets another settled sphere (φ0 when one is already
/// pressed against, kHalfPi when none is met before the equator).
double first_sphere_on(const SettledGrid& grid, const Meridian& m, double r, double r_max,
                       double top) {
    double end = kHalfPi;
    const double reach = r + r_max;
    const Vec3 lo(m.cj.x() - m.D - reach, m.cj.y() - reach, m.cj.z() - m.D - reach);
    const Vec3 hi(m.cj.x() + m.D + reach, top + reach, m.cj.z() + m.D + reach);
    grid.for_each_in_box(lo, hi, [&](const Sphere& k) {
        const Vec3 a(m.cj.x() - k.x, m.cj.y() - k.y, m.cj.z() - k.z);
        const double Dk = r + k.r;
        const double A = 2.0 * m.D * a.dot(m.u);
        const double B = 2.0 * m.D * a.y();
        const double C = Dk * Dk - a.squaredNorm() - m.D * m.D;
        const double R = std::hypot(A, B);
        if (R == 0.0) {
            return;  // the support itself
        }
        const double alpha = std::atan2(A, B);
        const double now = R * std::cos(m.phi0 - alpha) - C;
        if (now < -1e-12 * m.D * m.D) {
            end = std::min(end, m.phi0);  // already touching and pressing: cannot roll
            return;
        }
        if (std::abs(C) > R) {
            return;  // never touches along this circle
        }
        end = std::min(end, next_angle_after(alpha + std::acos(C / R), m.phi0));
    });
    return end;
}

/// First φ ≥ φ0 where the meridian meets the floor or a side wall (kHalfPi when none).
double first_plane_on(const Container& box, const Meridian& m, double r) {
    double end = kHalfPi;
    const double floor_cos = (box.floor + r - m.cj.y()) / m.D;
    if (floor_cos > -1.0 && floor_cos < 1.0) {
        const double at = std::acos(floor_cos);
        if (at >= m.phi0)
            end = std::min(end, at);
    }
    const auto wall = [&](double center, double direction, double bound) {
        if (direction == 0.0)
            return;
        const double sine = (bound - center) / (m.D * direction);
        if (sine >= std::sin(m.phi0) && sine <= 1.0)
            end = std::min(end, std::asin(sine));
    };
    if (!box.periodic) {
        wall(m.cj.x(), m.u.x(), m.u.x() > 0 ? box.x_max - r : box.x_min + r);
        wall(m.cj.z(), m.u.z(), m.u.z() > 0 ? box.z_max - r : box.z_min + r);
    }
    return end;
}

}  // namespace

DropOutcome apply_contact_model(ContactModel model, const SettledGrid& grid,
                                const Container& container, double r_max, const Vec3& c, double r,
                                StopReason reason, long moves) {
    if (model == ContactModel::None) {
        return DropOutcome{c, reason, moves};
    }
    // Closes a step fall's gap.
    const FirstContact hit = first_contact_below(grid, container, r_max, c, r);
    const Vec3 dropped(c.x(), hit.y, c.z());
    if (hit.on_floor) {
        return DropOutcome{dropped, StopReason::Floor, moves};
    }
    if (model == ContactModel::Settle) {
        return DropOutcome{roll_over_support(grid, container, r_max, dropped, r, hit.support),
                           reason, moves};
    }
    return outcome_of(roll_to_rest(grid, container, r_max, dropped, r, hit.support), reason, moves);
}

Vec3 roll_over_support(const SettledGrid& grid, const Container& container, double r_max,
                       const Vec3& c, double r, const Sphere& j) {
    const double D = r + j.r;
    Vec3 u(c.x() - j.x, 0.0, c.z() - j.z);
    const double horizontal = u.norm();
    if (horizontal < 1e-12 * D) {
        return c;  // exactly on top: no downhill direction
    }
    u /= horizontal;
    const Meridian m{Vec3(j.x, j.y, j.z), u, D, std::atan2(horizontal, c.y() - j.y)};
    if (m.phi0 >= kHalfPi) {
        return c;
    }
    const double end =
        std::min(first_sphere_on(grid, m, r, r_max, c.y()), first_plane_on(container, m, r));
    if (end >= kHalfPi || end <= m.phi0) {
        return c;
    }
    Vec3 p = m.cj + D * (std::sin(end) * u + std::cos(end) * Vec3::UnitY());
    if (!container.periodic) {
        p.x() = std::clamp(p.x(), container.x_min + r, container.x_max - r);
        p.z() = std::clamp(p.z(), container.z_min + r, container.z_max - r);
    }
    p.y() = std::max(p.y(), container.floor + r);
    return clear_at(grid, container, r_max, p, r) ? p : c;
}

}  // namespace sgmp::engine
