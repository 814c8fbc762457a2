#include "sgmp/metrics/bond_order.hpp"

#include <cmath>
#include <numbers>

namespace sgmp::metrics {
namespace {

/// √(13/(4π) · (6−m)!/(6+m)!), the normalisation of Y_6m.
const std::array<double, 7>& normalisation() {
    static const std::array<double, 7> values = [] {
        std::array<double, 7> n{};
        for (int m = 0; m <= 6; ++m) {
            double ratio = 1.0;  // (6−m)!/(6+m)!
            for (int k = 6 - m + 1; k <= 6 + m; ++k) {
                ratio /= k;
            }
            n[m] = std::sqrt(13.0 / (4.0 * std::numbers::pi) * ratio);
        }
        return n;
    }();
    return values;
}

/// d^m/dx^m of the Legendre polynomial P_6(x) = (231x⁶ − 315x⁴ + 105x² − 5)/16.
std::array<double, 7> legendre6_derivatives(double x) {
    const double x2 = x * x;
    return {(((231.0 * x2 - 315.0) * x2 + 105.0) * x2 - 5.0) / 16.0,
            ((1386.0 * x2 - 1260.0) * x2 + 210.0) * x / 16.0,
            ((6930.0 * x2 - 3780.0) * x2 + 210.0) / 16.0,
            (27720.0 * x2 - 7560.0) * x / 16.0,
            (83160.0 * x2 - 7560.0) / 16.0,
            166320.0 * x / 16.0,
            166320.0 / 16.0};
}

}  // namespace

void BondSums::add(const Vec3& unit) {
    // Y_6m ∝ P_6^(m)(cos θ) · (sin θ e^{iφ})^m with sin θ e^{iφ} = u_x + i u_y.
    const auto& n = normalisation();
    const auto derivative = legendre6_derivatives(unit.z());
    const std::complex<double> w(unit.x(), unit.y());
    std::complex<double> power(1.0, 0.0);
    for (int m = 0; m <= 6; ++m) {
        y[m] += n[m] * derivative[m] * power;
        power *= w;
    }
    ++bonds;
}

void BondSums::add(const BondSums& other) {
    for (int m = 0; m <= 6; ++m) {
        y[m] += other.y[m];
    }
    bonds += other.bonds;
}

double BondSums::q6() const {
    if (bonds == 0) {
        return 0.0;
    }
    const double scale = 1.0 / static_cast<double>(bonds);
    double sum = std::norm(y[0] * scale);
    for (int m = 1; m <= 6; ++m) {
        sum += 2.0 * std::norm(y[m] * scale);
    }
    return std::sqrt(4.0 * std::numbers::pi / 13.0 * sum);
}

}  // namespace sgmp::metrics
