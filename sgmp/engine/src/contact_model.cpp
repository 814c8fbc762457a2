// The §10.2 contact model: a particle the protocol leaves resting is settled into contact
// with its supports. Part of `Protocol` (see protocol.hpp, ContactModel::Settle).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sgmp/engine/protocol.hpp"
#include "sgmp/engine/rolling.hpp"

namespace sgmp::engine {

namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

/// Smallest angle ≥ from (up to rounding) congruent to `angle` modulo 2π.
double next_angle_after(double angle, double from) {
    const double turn = 2.0 * std::numbers::pi;
    return angle + turn * std::ceil((from - angle) / turn - 1e-12);
}

}  // namespace

DropOutcome Protocol::rest(Vec3 c, double r, StopReason reason, long moves) {
    if (params_.contact == ContactModel::None) {
        return DropOutcome{c, reason, moves};
    }
    const Fall hit = fall_exact(c, r);  // closes a step-mode gap
    c.y() = hit.y;
    if (hit.on_floor) {
        return DropOutcome{c, StopReason::Floor, moves};
    }
    if (params_.contact == ContactModel::Settle) {
        return DropOutcome{roll(c, r, hit.support), reason, moves};
    }
    const RollResult rolled = roll_to_rest(grid_, container_, max_radius_, c, r, hit.support);
    switch (rolled.end) {
        case RollEnd::Floor:
            return DropOutcome{rolled.center, StopReason::Floor, moves};
        case RollEnd::Wall:
            return DropOutcome{rolled.center, StopReason::Wall, moves};
        default:
            return DropOutcome{rolled.center, reason, moves};
    }
}

// The centre moves on the sphere of radius D = r + r_j about the support j, down the
// meridian away from it: p(φ) = c_j + D (sin φ·u + cos φ·ŷ), φ from its current value φ0
// towards the equator π/2, u the horizontal unit vector from c_j to the centre. Against
// another sphere k (a = c_j − c_k, D_k = r + r_k):
//   |p(φ) − c_k|² − D_k² = A sin φ + B cos φ − C = R cos(φ − α) − C,
//   A = 2D a·u, B = 2D a_y, C = D_k² − |a|² − D², R = √(A² + B²), α = atan2(A, B),
// which turns negative (contact) at φ = α + acos(C / R). The floor is met at
// cos φ = (floor + r − y_j)/D, a wall at sin φ = (wall ∓ r − x_j)/(D u_x) (same for z).
// The roll ends at the first of these; if none comes before the equator the particle is
// left where it was (it would fall off, which the protocol has already ruled out).
Vec3 Protocol::roll(const Vec3& c, double r, const Sphere& j) {
    const Vec3 cj(j.x, j.y, j.z);
    const double D = r + j.r;
    Vec3 u(c.x() - j.x, 0.0, c.z() - j.z);
    const double horizontal = u.norm();
    if (horizontal < 1e-12 * D) {
        return c;  // exactly on top: no downhill direction
    }
    u /= horizontal;
    const double phi0 = std::atan2(horizontal, c.y() - j.y);
    if (phi0 >= kHalfPi) {
        return c;
    }
    double end = kHalfPi;
    const double reach = r + max_radius_;
    const Vec3 lo(j.x - D - reach, j.y - reach, j.z - D - reach);
    const Vec3 hi(j.x + D + reach, c.y() + reach, j.z + D + reach);
    grid_.for_each_in_box(lo, hi, [&](const Sphere& k) {
        const Vec3 a(j.x - k.x, j.y - k.y, j.z - k.z);
        const double Dk = r + k.r;
        const double A = 2.0 * D * a.dot(u);
        const double B = 2.0 * D * a.y();
        const double C = Dk * Dk - a.squaredNorm() - D * D;
        const double R = std::hypot(A, B);
        if (R == 0.0) {
            return;  // the support itself
        }
        const double alpha = std::atan2(A, B);
        const double now = R * std::cos(phi0 - alpha) - C;
        if (now < -1e-12 * D * D) {
            end = std::min(end, phi0);  // already touching and pressing: cannot roll
            return;
        }
        if (std::abs(C) > R) {
            return;  // never touches along this circle
        }
        const double enter = next_angle_after(alpha + std::acos(C / R), phi0);
        end = std::min(end, enter);
    });
    const double floor_cos = (container_.floor + r - j.y) / D;
    if (floor_cos > -1.0 && floor_cos < 1.0) {
        const double at = std::acos(floor_cos);
        if (at >= phi0)
            end = std::min(end, at);
    }
    const auto wall = [&](double centre, double direction, double bound) {
        if (direction == 0.0)
            return;
        const double sine = (bound - centre) / (D * direction);
        if (sine >= std::sin(phi0) && sine <= 1.0)
            end = std::min(end, std::asin(sine));
    };
    wall(j.x, u.x(), u.x() > 0 ? container_.x_max - r : container_.x_min + r);
    wall(j.z, u.z(), u.z() > 0 ? container_.z_max - r : container_.z_min + r);
    if (end >= kHalfPi || end <= phi0) {
        return c;
    }
    Vec3 p = cj + D * (std::sin(end) * u + std::cos(end) * Vec3::UnitY());
    p.x() = std::clamp(p.x(), container_.x_min + r, container_.x_max - r);
    p.z() = std::clamp(p.z(), container_.z_min + r, container_.z_max - r);
    p.y() = std::max(p.y(), container_.floor + r);
    // Guard against rounding near tangency: never accept an overlap the protocol would not.
    bool clear = true;
    grid_.for_each_in_box(p - Vec3::Constant(reach), p + Vec3::Constant(reach),
                          [&](const Sphere& k) {
                              const double gap = (p - Vec3(k.x, k.y, k.z)).norm() - (r + k.r);
                              clear = clear && gap >= -1e-12 * D;
                          });
    return clear ? p : c;
}

}  // namespace sgmp::engine
