#include "sgmp/pack/pack_overlaps.hpp"

#include <algorithm>

namespace sgmp {

double max_radius(const std::vector<Particle>& particles) {
    double r_max = 0.0;
    for (const Particle& p : particles) {
        r_max = std::max(r_max, p.radius);
    }
    return r_max;
}

OverlapSearch::OverlapSearch(const std::vector<Particle>& particles) : particles_(particles) {
    r_max_ = max_radius(particles);
    if (particles.size() < 2 || !(r_max_ > 0.0)) {
        return;
    }
    double r_min = r_max_;
    double r_small = 0.0;  // the largest radius ≤ r_max / 2
    for (const Particle& p : particles) {
        r_min = std::min(r_min, p.radius);
        if (p.radius <= 0.5 * r_max_) {
            r_small = std::max(r_small, p.radius);
        }
    }
    double reach = 2.0 * r_max_;
    if (r_max_ > 2.0 * r_min) {  // a wide blend: cells for the small spheres
        reach = 2.0 * r_small;
        is_large_.assign(particles.size(), 0);
        for (std::size_t i = 0; i < particles.size(); ++i) {
            if (particles[i].radius > 0.5 * r_max_) {
                large_.push_back(i);
                is_large_[i] = 1;
            }
        }
    }
    reach_squared_ = reach * reach;
    grid_.emplace(centers_of(particles), reach);
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
