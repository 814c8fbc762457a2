#include "sgmp/metrics/ball_box_volume.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "sgmp/pack/ball_cut.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"

namespace sgmp::metrics {
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

}  // namespace sgmp::metrics
