#include "sgmp/metrics/mixing_profile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sgmp::metrics {
namespace {

/// Volume of the ball of radius r below u, measured from its centre.
double volume_below(double r, double u) {
    const double a = std::clamp(u, -r, r) + r;  // cap height from the bottom
    return std::numbers::pi * a * a * (3.0 * r - a) / 3.0;
}

}  // namespace

double ball_slab_volume(double r, double c, double y0, double y1) {
    return std::max(0.0, volume_below(r, y1 - c) - volume_below(r, y0 - c));
}

std::optional<MixingProfile> mixing_profile(const std::vector<Particle>& particles, double floor) {
    if (!has_species(particles)) {
        return std::nullopt;
    }
    MixingProfile p;
    double top = floor;
    double d_max = 0.0;
    for (const Particle& s : particles) {
        top = std::max(top, s.center.y() + s.radius);
        d_max = std::max(d_max, 2.0 * s.radius);
        p.species.push_back(s.species);
    }
    std::sort(p.species.begin(), p.species.end());
    p.species.erase(std::unique(p.species.begin(), p.species.end()), p.species.end());
    p.y_low = floor;
    p.y_high = top - d_max;
    if (!(p.y_high > p.y_low)) {
        return std::nullopt;
    }
    const std::size_t k = p.species.size();
    std::array<std::vector<double>, 4> volume;
    volume.fill(std::vector<double>(k, 0.0));
    const double slab = (p.y_high - p.y_low) / 4.0;
    for (const Particle& s : particles) {
        const std::size_t index = static_cast<std::size_t>(
            std::lower_bound(p.species.begin(), p.species.end(), s.species) - p.species.begin());
        for (std::size_t q = 0; q < 4; ++q) {
            const double y0 = p.y_low + static_cast<double>(q) * slab;
            const double y1 = q == 3 ? p.y_high : y0 + slab;
            volume[q][index] += ball_slab_volume(s.radius, s.center.y(), y0, y1);
        }
    }
    p.overall.assign(k, 0.0);
    double total = 0.0;
    for (std::size_t q = 0; q < 4; ++q) {
        double in_quarter = 0.0;
        for (std::size_t i = 0; i < k; ++i) {
            in_quarter += volume[q][i];
            p.overall[i] += volume[q][i];
        }
        total += in_quarter;
        p.quarters[q].assign(k, 0.0);
        for (std::size_t i = 0; i < k; ++i) {
            p.quarters[q][i] = in_quarter > 0.0 ? volume[q][i] / in_quarter : 0.0;
        }
    }
    for (double& share : p.overall) {
        share = total > 0.0 ? share / total : 0.0;
    }
    for (std::size_t q = 0; q < 4; ++q) {
        for (std::size_t i = 0; i < k; ++i) {
            p.deviation = std::max(p.deviation, std::abs(p.quarters[q][i] - p.overall[i]));
        }
    }
    return p;
}

}  // namespace sgmp::metrics
