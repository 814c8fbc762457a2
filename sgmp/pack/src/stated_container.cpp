#include "sgmp/pack/stated_container.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/metadata.hpp"

namespace sgmp {
namespace {

std::string three_digits(double value) {
    std::array<char, 32> text{};
    std::snprintf(text.data(), text.size(), "%.3g", value);
    return text.data();
}

bool periodic_sides(const Pack& pack) {
    return pack.metadata.get("sides").value_or("walls") == "periodic";
}

/// The file's own container (its header's), with the error naming the file.
std::optional<Container> header_container(const Pack& pack, const std::string& source) {
    const auto text = pack.metadata.get("container");
    if (!text) {
        return std::nullopt;
    }
    try {
        return Container::parse(*text);
    } catch (const std::invalid_argument& error) {
        throw InputError(source, 0, error.what());
    }
}

/// A statement of the user must agree with the file's own container (which then stands).
void check_agrees(const StatedContainer& stated, const Container& own, const std::string& source) {
    if (!same_container(own, stated.walls)) {
        throw InputError(source, 0,
                         stated.by + " container '" + stated.walls.to_string() +
                             "' contradicts the file's own container '" + own.to_string() +
                             "' (x_min x_max z_min z_max floor)");
    }
}

/// The file's box as its container, when the spheres reach it.
Container reached_box(const Pack& pack, const Container& box, const std::string& source) {
    if (!(box.x_min < box.x_max) || !(box.z_min < box.z_max)) {
        throw InputError(source, 0,
                         "no container stated, and the box '" + box.to_string() +
                             "' (x_min x_max z_min z_max floor) has no width: state the walls "
                             "with --container \"x_min x_max z_min z_max floor\"");
    }
    const BoxClearance clearance = largest_box_clearance(pack.particles, box, mean_diameter(pack));
    if (clearance.gap_over_d > kBoxReachOverD) {
        throw InputError(
            source, 0,
            "no container stated, and the spheres keep " + three_digits(clearance.gap_over_d) +
                " d of clearance beyond contact from the box's " + clearance.face +
                (clearance.face == "floor" ? "" : " side") + " (more than " +
                three_digits(kBoxReachOverD) +
                " d): a simulation box is not a container; state the walls with --container "
                "\"x_min x_max z_min z_max floor\" or a manifest column container");
    }
    return box;
}

}  // namespace

BoxClearance largest_box_clearance(const std::vector<Particle>& particles, const Container& box,
                                   double mean_d) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    // Nearest-sphere clearance of each face: x_min, x_max, z_min, z_max, floor.
    std::array<double, 5> nearest{kInfinity, kInfinity, kInfinity, kInfinity, kInfinity};
    for (const Particle& p : particles) {
        const Vec3& c = p.center;
        nearest[0] = std::min(nearest[0], c.x() - p.radius - box.x_min);
        nearest[1] = std::min(nearest[1], box.x_max - (c.x() + p.radius));
        nearest[2] = std::min(nearest[2], c.z() - p.radius - box.z_min);
        nearest[3] = std::min(nearest[3], box.z_max - (c.z() + p.radius));
        nearest[4] = std::min(nearest[4], c.y() - p.radius - box.floor);
    }
    const std::array<const char*, 5> names{"x_min", "x_max", "z_min", "z_max", "floor"};
    BoxClearance largest{0.0, "floor"};
    if (particles.empty() || !(mean_d > 0.0)) {
        return largest;
    }
    largest.gap_over_d = -kInfinity;
    for (std::size_t face = box.periodic ? 4 : 0; face < nearest.size(); ++face) {
        const double gap = nearest[face] / mean_d;
        if (gap > largest.gap_over_d) {
            largest = {gap, names[face]};
        }
    }
    return largest;
}

std::optional<std::size_t> first_centre_outside(const std::vector<Particle>& particles,
                                                const Container& walls) {
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Vec3& c = particles[i].center;
        const bool across = walls.periodic || (c.x() >= walls.x_min && c.x() <= walls.x_max &&
                                               c.z() >= walls.z_min && c.z() <= walls.z_max);
        if (!(across && c.y() >= walls.floor)) {
            return i;
        }
    }
    return std::nullopt;
}

bool same_container(const Container& a, const Container& b) {
    const double size =
        std::max({std::abs(a.x_min), std::abs(a.x_max), std::abs(a.z_min), std::abs(a.z_max),
                  std::abs(a.floor), a.x_max - a.x_min, a.z_max - a.z_min});
    const double tolerance = 1e-9 * size;
    return std::abs(a.x_min - b.x_min) <= tolerance && std::abs(a.x_max - b.x_max) <= tolerance &&
           std::abs(a.z_min - b.z_min) <= tolerance && std::abs(a.z_max - b.z_max) <= tolerance &&
           std::abs(a.floor - b.floor) <= tolerance;
}

void settle_container(Pack& pack, const std::optional<StatedContainer>& stated,
                      const std::optional<Container>& file_box, const std::string& source) {
    const std::optional<Container> own = header_container(pack, source);
    Container walls;
    std::string from;
    if (stated && !own) {
        walls = stated->walls;
        from = stated->by;
    } else if (own) {
        if (stated) {
            check_agrees(*stated, *own, source);
        }
        walls = *own;
        from = pack.metadata.get("container_from").value_or("header");  // not recorded
    } else if (file_box && pack.metadata.contains("periodic_y")) {
        walls = *file_box;  // fully periodic: the box is the cell, its y lower bound no floor
        from = "periodic box";
    } else if (file_box) {
        Container box = *file_box;
        box.periodic = periodic_sides(pack);
        walls = reached_box(pack, box, source);
        from = "box";
    } else {
        return;  // an extended XYZ without a container: the testbed's (pack_extent.hpp)
    }
    walls.periodic = periodic_sides(pack);
    if (const auto outside = first_centre_outside(pack.particles, walls)) {
        const Particle& p = pack.particles[*outside];
        throw InputError(source, 0,
                         "sphere id " + std::to_string(p.id) + " at (" +
                             format_number(p.center.x()) + ", " + format_number(p.center.y()) +
                             ", " + format_number(p.center.z()) + ") lies outside the container '" +
                             walls.to_string() + "' (from " + from +
                             "; x_min x_max z_min z_max floor)");
    }
    if (from != "header") {
        pack.metadata.set("container", walls.to_string());
        pack.metadata.set("container_from", from);
    }
}

}  // namespace sgmp
