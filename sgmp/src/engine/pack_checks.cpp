#include "sgmp/engine/pack_checks.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "sgmp/engine/settled_grid.hpp"

namespace sgmp::engine {

PackCheck check_pack(const std::vector<Particle>& particles, const Container& container,
                     double overlap_tolerance, double support_tolerance) {
    PackCheck result;
    if (particles.empty()) {
        return result;
    }
    double r_max = 0.0;
    for (const Particle& p : particles) {
        r_max = std::max(r_max, p.radius);
    }
    SettledGrid grid(container, 2.0 * r_max);
    for (const Particle& p : particles) {
        grid.insert(Sphere{p.center.x(), p.center.y(), p.center.z(), p.radius});
    }
    for (const Particle& p : particles) {
        const Vec3& c = p.center;
        const double r = p.radius;
        if (container.penetration(c, r) > overlap_tolerance) {
            ++result.outside;
        }
        bool supported = c.y() - r - container.floor <= support_tolerance ||
                         c.x() - r - container.x_min <= support_tolerance ||
                         container.x_max - c.x() - r <= support_tolerance ||
                         c.z() - r - container.z_min <= support_tolerance ||
                         container.z_max - c.z() - r <= support_tolerance;
        const double reach = r + r_max + support_tolerance;
        const Vec3 span = Vec3::Constant(reach);
        grid.for_each_in_box(c - span, c + span, [&](const Sphere& s) {
            const double gap =
                std::sqrt((c.x() - s.x) * (c.x() - s.x) + (c.y() - s.y) * (c.y() - s.y) +
                          (c.z() - s.z) * (c.z() - s.z)) -
                r - s.r;
            const bool self = s.x == c.x() && s.y == c.y() && s.z == c.z() && s.r == r;
            if (self) {
                return;
            }
            // Each pair is met twice; count it once (from the particle with the lower key).
            const bool first = std::tie(c.y(), c.x(), c.z()) < std::tie(s.y, s.x, s.z);
            if (gap < -overlap_tolerance && first) {
                ++result.overlaps;
            }
            if (first) {
                result.worst_gap = std::min(result.worst_gap, gap);
            }
            if (s.y <= c.y() && gap <= support_tolerance) {
                supported = true;
            }
        });
        result.unsupported += supported ? 0 : 1;
    }
    return result;
}

}  // namespace sgmp::engine
