#include "sgmp/pack/size_classes.hpp"

#include <algorithm>

namespace sgmp {

SizeClasses size_classes(const std::vector<Particle>& particles) {
    SizeClasses c;
    if (particles.empty()) {
        return c;
    }
    c.min_radius = particles.front().radius;
    for (const Particle& p : particles) {
        c.max_radius = std::max(c.max_radius, p.radius);
        c.min_radius = std::min(c.min_radius, p.radius);
    }
    for (const Particle& p : particles) {
        if (!c.large(p.radius)) {
            c.small_max_radius = std::max(c.small_max_radius, p.radius);
        }
    }
    return c;
}

}  // namespace sgmp
