#pragma once
// Independent O(N²) checks of the pack invariants, written without the engine's grid.
#include <algorithm>
#include <cmath>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::engine::testing {

/// Most negative surface gap over all pairs (+inf for fewer than two particles).
inline double worst_pair_gap(const std::vector<Particle>& ps) {
    double worst = INFINITY;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        for (std::size_t j = i + 1; j < ps.size(); ++j) {
            worst =
                std::min(worst, (ps[i].center - ps[j].center).norm() - ps[i].radius - ps[j].radius);
        }
    }
    return worst;
}

/// Largest crossing of a wall or the floor.
inline double worst_penetration(const std::vector<Particle>& ps, const Container& box) {
    double worst = 0.0;
    for (const Particle& p : ps) {
        worst = std::max(worst, box.penetration(p.center, p.radius));
    }
    return worst;
}

/// Distance from particle i to its nearest support: the floor, a wall, or a particle whose
/// centre is not higher (surface gap).
inline double support_distance(const std::vector<Particle>& ps, std::size_t i,
                               const Container& box) {
    const Particle& p = ps[i];
    const Vec3& c = p.center;
    double best = std::min({c.y() - p.radius - box.floor, c.x() - p.radius - box.x_min,
                            box.x_max - c.x() - p.radius, c.z() - p.radius - box.z_min,
                            box.z_max - c.z() - p.radius});
    for (std::size_t j = 0; j < ps.size(); ++j) {
        if (j != i && ps[j].center.y() <= c.y()) {
            best = std::min(best, (c - ps[j].center).norm() - p.radius - ps[j].radius);
        }
    }
    return best;
}

/// Largest support distance over the pack.
inline double worst_support_distance(const std::vector<Particle>& ps, const Container& box) {
    double worst = -INFINITY;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        worst = std::max(worst, support_distance(ps, i, box));
    }
    return worst;
}

}  // namespace sgmp::engine::testing
