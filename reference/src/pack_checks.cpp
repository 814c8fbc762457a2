#include "sgmp/reference/pack_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

namespace sgmp::reference {
namespace {

using Cell = std::tuple<long, long, long>;

Cell cell_of(const Vec3& c, double side) {
    return {static_cast<long>(std::floor(c.x() / side)),
            static_cast<long>(std::floor(c.y() / side)),
            static_cast<long>(std::floor(c.z() / side))};
}

}  // namespace

OverlapSummary pair_overlaps(const Pack& pack) {
    OverlapSummary summary;
    const auto& ps = pack.particles;
    double r_max = 0.0;
    for (const auto& p : ps) {
        r_max = std::max(r_max, p.radius);
    }
    if (ps.size() < 2 || r_max <= 0.0) {
        return summary;
    }
    const double side = 2.0 * r_max;  // overlapping centres are less than 2 r_max apart
    std::map<Cell, std::vector<std::size_t>> cells;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        cells[cell_of(ps[i].center, side)].push_back(i);
    }
    for (std::size_t i = 0; i < ps.size(); ++i) {
        const auto [cx, cy, cz] = cell_of(ps[i].center, side);
        for (long dx = -1; dx <= 1; ++dx) {
            for (long dy = -1; dy <= 1; ++dy) {
                for (long dz = -1; dz <= 1; ++dz) {
                    const auto found = cells.find({cx + dx, cy + dy, cz + dz});
                    if (found == cells.end()) {
                        continue;
                    }
                    for (const std::size_t j : found->second) {
                        if (j <= i) {
                            continue;
                        }
                        const double overlap = -surface_gap(ps[i], ps[j]);
                        if (overlap > 0.0) {
                            ++summary.overlapping_pairs;
                            summary.max_overlap = std::max(summary.max_overlap, overlap);
                        }
                    }
                }
            }
        }
    }
    return summary;
}

double max_wall_penetration(const Pack& pack, const Container& container) {
    double worst = 0.0;
    for (const auto& p : pack.particles) {
        worst = std::max(worst, container.penetration(p.center, p.radius));
    }
    return worst;
}

}  // namespace sgmp::reference
