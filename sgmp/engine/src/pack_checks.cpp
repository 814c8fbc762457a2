#include "sgmp/engine/pack_checks.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "sgmp/pack/cell_grid.hpp"
#include "sgmp/pack/pack_overlaps.hpp"

namespace sgmp::engine {

namespace {

/// Whether a sphere touches the floor or a wall within `tolerance`.
bool on_container(const Vec3& c, double r, const Container& container, double tolerance) {
    if (container.periodic) {
        return c.y() - r - container.floor <= tolerance;  // the floor is the only wall
    }
    return c.y() - r - container.floor <= tolerance || c.x() - r - container.x_min <= tolerance ||
           container.x_max - c.x() - r <= tolerance || c.z() - r - container.z_min <= tolerance ||
           container.z_max - c.z() - r <= tolerance;
}

/// Spheres neither on the container nor on a sphere whose centre is not higher (surface
/// gap ≤ tolerance).
std::size_t count_unsupported(const std::vector<Particle>& particles, const CellGrid& grid,
                              double r_max, const Container& container, double tolerance) {
    std::size_t unsupported = 0;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Vec3& c = particles[i].center;
        const double r = particles[i].radius;
        bool supported = on_container(c, r, container, tolerance);
        if (!supported) {
            grid.for_each_near(c, r + r_max + tolerance, [&](std::size_t j, double r2) {
                const Particle& s = particles[j];
                supported = supported || (j != i && s.center.y() <= c.y() &&
                                          std::sqrt(r2) - r - s.radius <= tolerance);
            });
        }
        unsupported += supported ? 0 : 1;
    }
    return unsupported;
}

}  // namespace

// Overlaps from the pack library's one overlap search (pack_overlaps.hpp); supports on a
// cell grid of side 2·r_max.
PackCheck check_pack(const std::vector<Particle>& particles, const Container& container,
                     double overlap_tolerance, double support_tolerance) {
    PackCheck result;
    if (particles.empty()) {
        return result;
    }
    const OverlapCount overlaps = count_overlaps(particles, container, overlap_tolerance);
    result.overlaps = overlaps.pairs;
    result.worst_gap = overlaps.max_pair > 0.0 ? -overlaps.max_pair : 0.0;
    result.outside = overlaps.walls;
    const double r_max = max_radius(particles);
    // With periodic sides a sphere may rest on one across a face: the grid's cells wrap.
    const CellGrid grid(centers_of(particles), 2.0 * r_max, NeighbourBox::of(container));
    result.unsupported = count_unsupported(particles, grid, r_max, container, support_tolerance);
    return result;
}

namespace {

/// Indices of `particles` in id order (the drop order).
std::vector<std::size_t> id_order(const std::vector<Particle>& particles) {
    std::vector<std::size_t> order(particles.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        order[i] = i;
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return particles[a].id < particles[b].id;
    });
    return order;
}

/// Unit normals (c_i − c_k)/|c_i − c_k| of the spheres k placed before i (lower id) within
/// surface gap `tolerance` of it.
void earlier_contact_normals(const std::vector<Particle>& particles, const CellGrid& grid,
                             double r_max, std::size_t i, double tolerance,
                             std::vector<Vec3>& normals) {
    const Particle& p = particles[i];
    normals.clear();
    grid.for_each_near(p.center, p.radius + r_max + tolerance, [&](std::size_t j, double) {
        const Particle& s = particles[j];
        if (!(s.id < p.id)) {
            return;  // itself, or placed after it
        }
        const double distance = (p.center - s.center).norm();
        if (distance - p.radius - s.radius <= tolerance) {
            normals.push_back((p.center - s.center) / distance);
        }
    });
}

/// Whether ŷ = Σ λ_k n_k with every λ_k ≥ −force_tolerance for some three of `normals`.
bool held_by_three(const std::vector<Vec3>& normals, double force_tolerance) {
    const std::size_t n = normals.size();
    for (std::size_t a = 0; a < n; ++a) {
        for (std::size_t b = a + 1; b < n; ++b) {
            for (std::size_t e = b + 1; e < n; ++e) {
                Eigen::Matrix3d m;
                m.col(0) = normals[a];
                m.col(1) = normals[b];
                m.col(2) = normals[e];
                if (std::abs(m.determinant()) < 1e-12) {
                    continue;
                }
                const Vec3 lambda = m.partialPivLu().solve(Vec3::UnitY());
                if (lambda.allFinite() && lambda.minCoeff() >= -force_tolerance) {
                    return true;
                }
            }
        }
    }
    return false;
}

}  // namespace

RestCheck check_rolled_rest(const std::vector<Particle>& particles, const Container& container,
                            double contact_tolerance, double force_tolerance) {
    RestCheck result;
    result.first = particles.size();
    if (particles.empty()) {
        return result;
    }
    const double r_max = max_radius(particles);
    const CellGrid grid(centers_of(particles), 2.0 * r_max);
    // Drop order is id order: each sphere is checked against the spheres placed before it.
    std::vector<Vec3> normals;
    for (const std::size_t i : id_order(particles)) {
        if (on_container(particles[i].center, particles[i].radius, container, contact_tolerance)) {
            continue;
        }
        earlier_contact_normals(particles, grid, r_max, i, contact_tolerance, normals);
        if (!held_by_three(normals, force_tolerance)) {
            ++result.unrested;
            result.fewer_than_three += normals.size() < 3 ? 1 : 0;
            result.first = std::min(result.first, i);
        }
    }
    return result;
}

}  // namespace sgmp::engine
