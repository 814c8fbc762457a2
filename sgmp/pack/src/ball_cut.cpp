#include "sgmp/pack/ball_cut.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sgmp {
namespace {

constexpr double kPi = std::numbers::pi;

/// ∫ (1 − x²) dx.
double cubic(double x) {
    return x - x * x * x / 3.0;
}

/// Antiderivative of A_h on [−c, c], for |h| < 1. acos(h/s) is taken as atan2(√(c² − x²), h)
/// with the same root as the atan term: near x = ±c both vary steeply and their rounding
/// errors then cancel (acos of a rounded h/s would lose half the digits there).
double antiderivative(double x, double h, double c2, double c) {
    x = std::clamp(x, -c, c);
    const double root = std::sqrt(std::max(0.0, (c - x) * (c + x)));  // exactly 0 at ±c
    const double arc = c > 0.0 ? std::asin(std::clamp(x / c, -1.0, 1.0)) : 0.0;
    const double i2 = 0.5 * c2 * arc - 0.5 * x * root;
    const double is = 0.5 * (x * root + c2 * arc);
    const double sign = h > 0.0 ? 1.0 : (h < 0.0 ? -1.0 : 0.0);
    // acos(h/s) is π/2 for h = 0 everywhere, including x = ±1 where atan2(0, 0) would say 0.
    const double polar = h == 0.0 ? 0.5 * kPi : std::atan2(root, h);
    return cubic(x) * polar + h * (i2 / 3.0 - 2.0 / 3.0 * arc - is) +
           2.0 / 3.0 * sign * std::atan2(std::abs(h) * x, root);
}

}  // namespace

double unit_ball_cut(double u0, double u1, double h) {
    u0 = std::clamp(u0, -1.0, 1.0);
    u1 = std::clamp(u1, -1.0, 1.0);
    if (u1 <= u0 || h >= 1.0) {
        return 0.0;
    }
    if (h <= -1.0) {
        return kPi * (cubic(u1) - cubic(u0));
    }
    const double c2 = 1.0 - h * h;
    const double c = std::sqrt(c2);
    // Middle part, |x| < c.
    const double m0 = std::max(u0, -c);
    const double m1 = std::min(u1, c);
    double volume = 0.0;
    if (m1 > m0) {
        volume += antiderivative(m1, h, c2, c) - antiderivative(m0, h, c2, c);
    }
    // Outer parts, |x| ≥ c: the whole slice disk lies above y = h when h < 0, none when h > 0.
    if (h < 0.0) {
        const double l1 = std::min(u1, -c);
        if (l1 > u0) {
            volume += kPi * (cubic(l1) - cubic(u0));
        }
        const double r0 = std::max(u0, c);
        if (u1 > r0) {
            volume += kPi * (cubic(u1) - cubic(r0));
        }
    }
    return std::max(0.0, volume);
}

double ball_cut_volume(double r, double x0, double x1, double y0, double y1) {
    if (!(r > 0.0) || y1 <= y0 || x1 <= x0) {
        return 0.0;
    }
    const double scale = r * r * r;
    const double u0 = x0 / r;
    const double u1 = x1 / r;
    return std::max(0.0, scale * (unit_ball_cut(u0, u1, y0 / r) - unit_ball_cut(u0, u1, y1 / r)));
}

}  // namespace sgmp
