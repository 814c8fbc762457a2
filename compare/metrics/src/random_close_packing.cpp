#include "sgmp/metrics/random_close_packing.hpp"

#include <cmath>

namespace sgmp::metrics {

SizeMoments size_moments(const std::vector<Particle>& particles) {
    SizeMoments m;
    if (particles.empty()) {
        return m;
    }
    const auto n = static_cast<double>(particles.size());
    double sum = 0.0;
    for (const Particle& p : particles) {
        sum += p.radius;
    }
    const double mean = sum / n;
    double second = 0.0;
    double third = 0.0;
    for (const Particle& p : particles) {
        const double u = p.radius - mean;
        second += u * u;
        third += u * u * u;
    }
    const double sd = std::sqrt(second / n);
    if (!(sd > 1e-14 * mean)) {  // one size, up to rounding
        return m;
    }
    m.polydispersity = sd / mean;
    m.skewness = third / n / (sd * sd * sd);
    return m;
}

std::optional<double> desmond_weeks_phi_rcp(const SizeMoments& m) {
    if (m.polydispersity > kDesmondWeeksMaxPolydispersity ||
        m.skewness < kDesmondWeeksMinSkewness || m.skewness > kDesmondWeeksMaxSkewness) {
        return std::nullopt;
    }
    return kDesmondWeeksPhiStar + kDesmondWeeksC1 * m.polydispersity +
           kDesmondWeeksC2 * m.skewness * m.polydispersity * m.polydispersity;
}

}  // namespace sgmp::metrics
