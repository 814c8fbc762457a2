#include "sgmp/pack/text_precision.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>

namespace sgmp {
namespace {

using Cell = std::array<std::int64_t, 3>;

Cell cell_of(const Vec3& p, double width) {
    return {static_cast<std::int64_t>(std::floor(p.x() / width)),
            static_cast<std::int64_t>(std::floor(p.y() / width)),
            static_cast<std::int64_t>(std::floor(p.z() / width))};
}

}  // namespace

PrecisionOverlaps precision_overlaps(const std::vector<Particle>& particles, int decimals,
                                     double floor) {
    PrecisionOverlaps result;
    result.bound = (std::sqrt(3.0) + 1.0) * std::pow(10.0, -decimals);
    double max_radius = 0.0;
    for (const auto& p : particles) {
        max_radius = std::max(max_radius, p.radius);
    }
    if (particles.size() < 2 || !(max_radius > 0.0)) {
        return result;
    }
    const double width = 2.0 * max_radius;
    std::map<Cell, std::vector<std::size_t>> cells;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        cells[cell_of(particles[i].center, width)].push_back(i);
    }
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Particle& a = particles[i];
        const Cell home = cell_of(a.center, width);
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
            for (std::int64_t dy = -1; dy <= 1; ++dy) {
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    const auto found = cells.find({home[0] + dx, home[1] + dy, home[2] + dz});
                    if (found == cells.end()) {
                        continue;
                    }
                    for (const std::size_t j : found->second) {
                        if (j <= i || !overlaps(a, particles[j])) {
                            continue;
                        }
                        const double depth = -surface_gap(a, particles[j]);
                        if (!(depth > floor)) {
                            continue;
                        }
                        ++result.overlaps;
                        if (depth <= result.bound) {
                            ++result.within_precision;
                            result.max_overlap = std::max(result.max_overlap, depth);
                        }
                    }
                }
            }
        }
    }
    return result;
}

}  // namespace sgmp
