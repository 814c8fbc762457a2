#include "sgmp/engine/hard_sphere_finish.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "sgmp/engine/settled_grid.hpp"
#include "sgmp/pack/periodic_images.hpp"

namespace sgmp::engine {

namespace {

/// Spheres in order of height (ties by index).
std::vector<std::size_t> by_height(const std::vector<Particle>& particles) {
    std::vector<std::size_t> order(particles.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return particles[a].center.y() < particles[b].center.y();
    });
    return order;
}

/// c between the walls (wrapped into the cell with periodic sides) and above the floor.
Vec3 inside(Vec3 c, double r, const Container& box) {
    if (box.periodic) {
        c = box.wrapped(c);
    } else {
        c.x() = std::clamp(c.x(), box.x_min + r, box.x_max - r);
        c.z() = std::clamp(c.z(), box.z_min + r, box.z_max - r);
    }
    c.y() = std::max(c.y(), box.floor + r);
    return c;
}

/// The placed sphere overlapping a sphere (c, r) most deeply (by more than tolerance), or
/// nullptr.
const Sphere* deepest_overlap(const std::vector<Sphere>& near, const Vec3& c, double r,
                              double tolerance) {
    const Sphere* deepest = nullptr;
    double worst = tolerance;
    for (const Sphere& s : near) {
        const double dx = c.x() - s.x, dy = c.y() - s.y, dz = c.z() - s.z;
        const double overlap = r + s.r - std::sqrt(dx * dx + dy * dy + dz * dz);
        if (overlap > worst) {
            worst = overlap;
            deepest = &s;
        }
    }
    return deepest;
}

void gather(const SettledGrid& placed, const Vec3& c, double reach, std::vector<Sphere>& near) {
    near.clear();
    const Vec3 span = Vec3::Constant(reach);
    placed.for_each_in_box(c - span, c + span, [&](const Sphere& s) { near.push_back(s); });
}

/// Where sphere (c, r) goes among the placed spheres; `lifted` tells whether it needed the
/// vertical lift.
Vec3 place(const SettledGrid& placed, Vec3 c, double r, double r_max, const Container& box,
           double tolerance, std::vector<Sphere>& near,
           std::vector<std::pair<double, double>>& scratch, bool& lifted) {
    c = inside(c, r, box);
    // Pushes move c by the overlaps, far less than the extra half radius gathered.
    gather(placed, c, 1.5 * r + r_max, near);
    for (int k = 0; k < kFinishProjections; ++k) {
        const Sphere* s = deepest_overlap(near, c, r, tolerance);
        if (s == nullptr) {
            break;
        }
        const Vec3 from(s->x, s->y, s->z);
        const Vec3 normal = c - from;
        const double distance = normal.norm();
        if (!(distance > 0.0)) {
            break;  // concentric: only the lift can help
        }
        c = inside(from + normal * ((r + s->r) / distance), r, box);
    }
    gather(placed, c, r + r_max, near);  // the exact check at the final place
    lifted = deepest_overlap(near, c, r, tolerance) != nullptr;
    if (lifted) {
        // A sphere of radius r − tolerance is blocked exactly where this one overlaps a
        // placed sphere by more than the tolerance.
        c.y() = lowest_free_height(placed, c.x(), c.z(), r - tolerance, r_max, c.y(), scratch);
    }
    return c;
}

}  // namespace

FinishStats finish_as_hard_spheres(std::vector<Particle>& particles, const Container& container,
                                   double tolerance) {
    FinishStats stats;
    double r_max = 0.0;
    for (const Particle& p : particles) {
        r_max = std::max(r_max, p.radius);
    }
    if (particles.empty() || !(r_max > 0.0)) {
        return stats;
    }
    SettledGrid placed(container, 2.0 * r_max);
    std::vector<Sphere> near;
    std::vector<std::pair<double, double>> scratch;
    for (const std::size_t i : by_height(particles)) {
        Particle& p = particles[i];
        bool lifted = false;
        const Vec3 c =
            place(placed, p.center, p.radius, r_max, container, tolerance, near, scratch, lifted);
        const double moved = (c - p.center).norm();
        stats.move_max = std::max(stats.move_max, moved);
        stats.move_sum += moved;
        stats.lifted += lifted ? 1 : 0;
        p.center = c;
        placed.insert(Sphere{c.x(), c.y(), c.z(), p.radius});
        // With periodic sides, its images across the faces too, as far as a later sphere's
        // searches reach from inside the cell (1.5·r + r_max, at most 2.5·r_max).
        for (const Vec3& image : periodic_image_centers(c, container, 3.0 * r_max)) {
            placed.insert(Sphere{image.x(), image.y(), image.z(), p.radius});
        }
    }
    return stats;
}

}  // namespace sgmp::engine
