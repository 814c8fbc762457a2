#include "sgmp/engine/pack_checks.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <Eigen/Dense>

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

RestCheck check_rolled_rest(const std::vector<Particle>& particles, const Container& container,
                            double contact_tolerance, double force_tolerance) {
    RestCheck result;
    result.first = particles.size();
    if (particles.empty()) {
        return result;
    }
    double r_max = 0.0;
    for (const Particle& p : particles) {
        r_max = std::max(r_max, p.radius);
    }
    // Drop order is id order: each sphere is checked against the spheres placed before it
    // (the grid holds exactly those), then added.
    std::vector<std::size_t> order(particles.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        order[i] = i;
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return particles[a].id < particles[b].id;
    });
    SettledGrid grid(container, 2.0 * r_max);
    std::vector<Vec3> normals;
    for (const std::size_t i : order) {
        const Particle& p = particles[i];
        const Vec3& c = p.center;
        const double r = p.radius;
        const double tol = contact_tolerance;
        grid.insert(Sphere{c.x(), c.y(), c.z(), r});
        if (c.y() - r - container.floor <= tol || c.x() - r - container.x_min <= tol ||
            container.x_max - c.x() - r <= tol || c.z() - r - container.z_min <= tol ||
            container.z_max - c.z() - r <= tol) {
            continue;
        }
        normals.clear();
        const Vec3 span = Vec3::Constant(r + r_max + tol);
        grid.for_each_in_box(c - span, c + span, [&](const Sphere& s) {
            const Vec3 sc(s.x, s.y, s.z);
            if (sc == c && s.r == r) {
                return;  // itself (inserted above)
            }
            const double distance = (c - sc).norm();
            if (distance - r - s.r > tol) {
                return;
            }
            normals.push_back((c - sc) / distance);
        });
        bool rests = false;
        const std::size_t n = normals.size();
        for (std::size_t a = 0; a < n && !rests; ++a) {
            for (std::size_t b = a + 1; b < n && !rests; ++b) {
                for (std::size_t e = b + 1; e < n && !rests; ++e) {
                    Eigen::Matrix3d m;
                    m.col(0) = normals[a];
                    m.col(1) = normals[b];
                    m.col(2) = normals[e];
                    if (std::abs(m.determinant()) < 1e-12) {
                        continue;
                    }
                    const Vec3 lambda = m.partialPivLu().solve(Vec3::UnitY());
                    rests = lambda.allFinite() && lambda.minCoeff() >= -force_tolerance;
                }
            }
        }
        if (!rests) {
            ++result.unrested;
            result.fewer_than_three += n < 3 ? 1 : 0;
            result.first = std::min(result.first, i);
        }
    }
    return result;
}

}  // namespace sgmp::engine
