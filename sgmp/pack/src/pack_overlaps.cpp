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
    const double r_max = max_radius(particles);
    if (particles.size() >= 2 && r_max > 0.0) {
        grid_.emplace(centers_of(particles), 2.0 * r_max);
    }
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
