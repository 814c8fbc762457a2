#include "sgmp/compare/ball_cut.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include <cmath>
#include <numbers>
#include "sgmp/pack/sphere_box_volume.hpp"

namespace sgmp::compare {
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

}  // namespace sgmp::compare

namespace sgmp::compare {
namespace {

constexpr int kNodes = 32;

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n, once).
struct GaussLegendre {
    std::array<double, kNodes> x{};
    std::array<double, kNodes> w{};
    GaussLegendre() {
        for (int i = 0; i < kNodes; ++i) {
            double z = std::cos(std::numbers::pi * (i + 0.75) / (kNodes + 0.5));
            double derivative = 1.0;
            for (int iteration = 0; iteration < 100; ++iteration) {
                double p0 = 1.0;
                double p1 = z;
                for (int k = 2; k <= kNodes; ++k) {
                    const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                derivative = kNodes * (z * p1 - p0) / (z * z - 1.0);
                const double step = p1 / derivative;
                z -= step;
                if (std::abs(step) < 1e-16) {
                    break;
                }
            }
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * derivative * derivative);
        }
    }
};

const GaussLegendre& gauss_legendre() {
    static const GaussLegendre rule;
    return rule;
}

/// ∫_a^b f(u) du with u = a + (b − a)(1 − cos t)/2, t ∈ [0, π].
template <class F>
double integrate_smoothed(F&& f, double a, double b) {
    const auto& rule = gauss_legendre();
    const double half = 0.5 * std::numbers::pi;
    double sum = 0.0;
    for (int i = 0; i < kNodes; ++i) {
        const double t = half * (rule.x[i] + 1.0);
        const double u = a + (b - a) * 0.5 * (1.0 - std::cos(t));
        sum += rule.w[i] * f(u) * 0.5 * (b - a) * std::sin(t);
    }
    return sum * half;
}

}  // namespace

double ball_box_volume(const Vec3& center, double r, const Box& box) {
    if (!(r > 0.0)) {
        return 0.0;
    }
    const Vec3 nearest = center.cwiseMax(box.lo).cwiseMin(box.hi);
    if ((nearest - center).squaredNorm() >= r * r) {
        return 0.0;
    }
    const Vec3 lo = box.lo - center;
    const Vec3 hi = box.hi - center;
    std::array<bool, 3> cut{};
    int cuts = 0;
    for (int axis = 0; axis < 3; ++axis) {
        cut[axis] = lo[axis] > -r || hi[axis] < r;
        cuts += cut[axis] ? 1 : 0;
    }
    const double ball = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    if (cuts == 0) {
        return ball;
    }
    if (cuts <= 2) {
        int first = -1;
        int second = -1;
        for (int axis = 0; axis < 3; ++axis) {
            if (cut[axis]) {
                (first < 0 ? first : second) = axis;
            }
        }
        if (second < 0) {
            second = (first + 1) % 3;  // an uncut axis acts as [−r, r]
        }
        return ball_cut_volume(r, std::max(lo[first], -r), std::min(hi[first], r),
                               std::max(lo[second], -r), std::min(hi[second], r));
    }
    // All three axes cut: integrate along y.
    const double u0 = std::max(lo.y(), -r);
    const double u1 = std::min(hi.y(), r);
    std::vector<double> breaks{u0, u1};
    const auto add_break = [&](double rho_squared) {
        const double u_squared = r * r - rho_squared;
        if (u_squared > 0.0) {
            const double u = std::sqrt(u_squared);
            for (const double candidate : {-u, u}) {
                if (candidate > u0 && candidate < u1) {
                    breaks.push_back(candidate);
                }
            }
        }
    };
    const std::array<double, 2> xs{lo.x(), hi.x()};
    const std::array<double, 2> zs{lo.z(), hi.z()};
    for (const double x : xs) {
        add_break(x * x);
        for (const double z : zs) {
            add_break(x * x + z * z);
        }
    }
    for (const double z : zs) {
        add_break(z * z);
    }
    std::sort(breaks.begin(), breaks.end());
    const auto slice = [&](double u) {
        const double rho = std::sqrt(std::max(0.0, r * r - u * u));
        return disk_rectangle_area(rho, lo.x(), hi.x(), lo.z(), hi.z());
    };
    double volume = 0.0;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        if (breaks[i + 1] > breaks[i]) {
            volume += integrate_smoothed(slice, breaks[i], breaks[i + 1]);
        }
    }
    return std::clamp(volume, 0.0, ball);
}

}  // namespace sgmp::compare
