#include "sgmp/pack/pack_overlaps.hpp"

#include "sgmp/pack/size_classes.hpp"

#include <algorithm>
#include <cmath>

namespace sgmp {

double max_radius(const std::vector<Particle>& particles) {
    double r_max = 0.0;
    for (const Particle& p : particles) {
        r_max = std::max(r_max, p.radius);
    }
    return r_max;
}

OverlapSearch::OverlapSearch(const std::vector<Particle>& particles) : particles_(particles) {
    const SizeClasses sizes = size_classes(particles);
    const double r_max = sizes.max_radius;
    if (particles.size() < 2 || !(r_max > 0.0)) {
        return;
    }
    // A wide blend: cells for the small spheres (size_classes.hpp).
    const double reach = sizes.wide() ? 2.0 * sizes.small_max_radius : 2.0 * r_max;
    grid_.emplace(centers_of(particles), reach);
    if (!sizes.wide()) {
        return;
    }
    const double reach_squared = reach * reach;
    std::vector<char> large(particles.size(), 0);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        large[i] = sizes.large(particles[i].radius) ? 1 : 0;
    }
    for (std::size_t l = 0; l < particles.size(); ++l) {
        if (large[l] == 0) {
            continue;
        }
        const Particle& a = particles[l];
        grid_->for_each_near(a.center, a.radius + r_max, [&](std::size_t k, double q) {
            if (q < reach_squared || a.radius + particles[k].radius - std::sqrt(q) <= 0.0) {
                return;  // the grid's own pass has it, or no overlap
            }
            if (k > l) {
                beyond_.emplace_back(l, k);
            } else if (k < l && large[k] == 0) {
                beyond_.emplace_back(k, l);  // a large pair is met from its first member
            }
        });
    }
    std::sort(beyond_.begin(), beyond_.end());
}

OverlapCount count_overlaps(const std::vector<Particle>& particles, const Container& container,
                            double tolerance) {
    OverlapCount count;
    for_each_overlap(
        particles, container,
        [&](std::size_t, std::size_t, double depth) {
            count.pairs += depth > tolerance ? 1 : 0;
            count.max_pair = std::max(count.max_pair, depth);
        },
        [&](std::size_t, double depth) {
            count.walls += depth > tolerance ? 1 : 0;
            count.max_wall = std::max(count.max_wall, depth);
        });
    return count;
}

}  // namespace sgmp
