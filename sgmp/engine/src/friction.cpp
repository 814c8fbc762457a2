#include "friction.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sgmp::engine {

namespace {

inline Triple cross(const Triple& a, const Triple& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// Updates the spring ξ of one contact of normal n (unit, from i to the other body) pressed
/// with the normal force fn, by the relative displacement du of the other body's surface;
/// returns the tangential force on i.
inline Triple load_spring(Triple& xi, const Triple& n, const Triple& du, double fn, double kt,
                          double mu) {
    xi.x += du.x;
    xi.y += du.y;
    xi.z += du.z;
    const double along = xi.x * n.x + xi.y * n.y + xi.z * n.z;
    xi.x -= along * n.x;
    xi.y -= along * n.y;
    xi.z -= along * n.z;
    const double length = std::sqrt(xi.x * xi.x + xi.y * xi.y + xi.z * xi.z);
    const double cap = mu * fn;
    if (kt * length > cap) {
        const double shrink = cap / (kt * length);
        xi.x *= shrink;
        xi.y *= shrink;
        xi.z *= shrink;
    }
    return {kt * xi.x, kt * xi.y, kt * xi.z};
}

inline void add(Triple& a, const Triple& b, double sign) {
    a.x += sign * b.x;
    a.y += sign * b.y;
    a.z += sign * b.z;
}

void add_pair_forces(State& s, double k, double kt, double mu) {
    const std::vector<Ball>& p = s.spheres;
    for (std::size_t i = 0; i < p.size(); ++i) {
        std::size_t slot = s.neighbours.first_slot(i);
        for (const std::uint32_t j : s.neighbours.of(i)) {
            Triple& xi = s.pair_spring[slot++];
            double dx = p[j].x - p[i].x, dz = p[j].z - p[i].z;
            const double dy = p[j].y - p[i].y;
            s.sides.to_nearest_image(dx, dz);
            const double reach = p[i].r + p[j].r;
            const double d2 = dx * dx + dy * dy + dz * dz;
            if (d2 >= reach * reach) {
                xi = Triple{};
                continue;
            }
            const double dist = std::sqrt(d2);
            const Triple n{dx / dist, dy / dist, dz / dist};
            const Triple roll = cross({s.rolled[i].x + s.rolled[j].x, s.rolled[i].y + s.rolled[j].y,
                                       s.rolled[i].z + s.rolled[j].z},
                                      n);
            const Triple du{s.moved[j].x - s.moved[i].x - roll.x,
                            s.moved[j].y - s.moved[i].y - roll.y,
                            s.moved[j].z - s.moved[i].z - roll.z};
            const Triple ft = load_spring(xi, n, du, k * (reach - dist), kt, mu);
            add(s.f[i], ft, 1.0);
            add(s.f[j], ft, -1.0);
            const Triple torque = cross(n, ft);
            add(s.g[i], torque, 1.0);
            add(s.g[j], torque, 1.0);
        }
    }
}

void add_wall_forces(State& s, const Container& box, double k, double kt, double mu) {
    const std::vector<Ball>& p = s.spheres;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = p[i].r;
        // Penetration and the unit normal towards each wall: x_min, x_max, z_min, z_max, floor.
        const double depth[5] = {box.x_min + r - p[i].x, p[i].x + r - box.x_max,
                                 box.z_min + r - p[i].z, p[i].z + r - box.z_max,
                                 box.floor + r - p[i].y};
        static constexpr Triple kNormal[5] = {
            {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}, {0.0, -1.0, 0.0}};
        for (int w = box.periodic ? 4 : 0; w < 5; ++w) {  // periodic sides: the floor alone
            Triple& xi = s.wall_spring[5 * i + static_cast<std::size_t>(w)];
            if (depth[w] <= 0.0) {
                xi = Triple{};
                continue;
            }
            const Triple& n = kNormal[w];
            const Triple roll = cross(s.rolled[i], n);
            const Triple du{-s.moved[i].x - roll.x, -s.moved[i].y - roll.y, -s.moved[i].z - roll.z};
            const Triple ft = load_spring(xi, n, du, k * depth[w], kt, mu);
            add(s.f[i], ft, 1.0);
            add(s.g[i], cross(n, ft), 1.0);
        }
    }
}

}  // namespace

void enable_friction(State& s, double tangential_ratio, double friction) {
    const std::size_t n = s.spheres.size();
    s.frictional = true;
    s.tangential_ratio = tangential_ratio;
    s.friction = friction;
    s.w.assign(n, Triple{});
    s.g.assign(n, Triple{});
    s.moved.assign(n, Triple{});
    s.rolled.assign(n, Triple{});
    s.pair_spring.assign(s.neighbours.pairs(), Triple{});
    s.wall_spring.assign(5 * n, Triple{});
}

void carry_springs(State& s) {
    std::vector<Triple> carried(s.neighbours.pairs(), Triple{});
    for (std::size_t i = 0; i < s.spheres.size(); ++i) {
        const auto old = s.previous.of(i);
        const std::size_t old_first = s.previous.first_slot(i);
        std::size_t slot = s.neighbours.first_slot(i);
        for (const std::uint32_t j : s.neighbours.of(i)) {
            const auto found = std::find(old.begin(), old.end(), j);
            if (found != old.end()) {
                carried[slot] =
                    s.pair_spring[old_first + static_cast<std::size_t>(found - old.begin())];
            }
            ++slot;
        }
    }
    s.pair_spring.swap(carried);
}

void add_tangential_forces(State& s, const Container& box, double k) {
    const double kt = s.tangential_ratio * k;
    const double mu = s.friction;
    std::fill(s.g.begin(), s.g.end(), Triple{});
    add_pair_forces(s, k, kt, mu);
    add_wall_forces(s, box, k, kt, mu);
    std::fill(s.moved.begin(), s.moved.end(), Triple{});
    std::fill(s.rolled.begin(), s.rolled.end(), Triple{});
}

void scale_springs(State& s, double factor) {
    for (Triple& xi : s.pair_spring) {
        xi = {factor * xi.x, factor * xi.y, factor * xi.z};
    }
    for (Triple& xi : s.wall_spring) {
        xi = {factor * xi.x, factor * xi.y, factor * xi.z};
    }
}

}  // namespace sgmp::engine
