#include "sgmp/pack/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/parameter_error.hpp"

namespace sgmp {

std::string Container::to_string() const {
    return format_number(x_min) + " " + format_number(x_max) + " " + format_number(z_min) + " " +
           format_number(z_max) + " " + format_number(floor);
}

Container Container::parse(const std::string& text) {
    std::istringstream in(text);
    Container c;
    std::string rest;
    if (!(in >> c.x_min >> c.x_max >> c.z_min >> c.z_max >> c.floor) || (in >> rest) ||
        !std::isfinite(c.x_min) || !std::isfinite(c.x_max) || !std::isfinite(c.z_min) ||
        !std::isfinite(c.z_max) || !std::isfinite(c.floor)) {
        throw ParameterError("container", "'" + text + "'",
                             "must be five finite numbers: x_min x_max z_min z_max floor");
    }
    if (!(c.x_min < c.x_max) || !(c.z_min < c.z_max)) {
        throw ParameterError("container", "'" + text + "'",
                             "must have x_min < x_max and z_min < z_max (x_min x_max z_min "
                             "z_max floor)");
    }
    return c;
}

double Container::penetration(const Vec3& center, double radius) const {
    if (periodic) {
        return std::max(0.0, floor - (center.y() - radius));
    }
    const double worst = std::max({x_min - (center.x() - radius), (center.x() + radius) - x_max,
                                   z_min - (center.z() - radius), (center.z() + radius) - z_max,
                                   floor - (center.y() - radius)});
    return std::max(0.0, worst);
}

Vec3 Container::wrapped(const Vec3& center) const {
    if (!periodic) {
        return center;
    }
    const auto wrap = [](double v, double lo, double hi) {
        const double period = hi - lo;
        double w = v - period * std::floor((v - lo) / period);
        if (w >= hi) {  // rounding at the upper face
            w -= period;
        }
        return w < lo ? lo : w;
    };
    return Vec3(wrap(center.x(), x_min, x_max), center.y(), wrap(center.z(), z_min, z_max));
}

Box Container::box_up_to(double top) const {
    return Box{Vec3(x_min, floor, z_min), Vec3(x_max, top, z_max)};
}

Box control_volume() {
    const double half = 0.5 * kControlSide;
    return Box{Vec3(-half, -half, -half), Vec3(half, half, half)};
}

double diameter_for_count(std::size_t count, double phi_target) {
    if (count == 0) {
        throw std::invalid_argument("count must be at least 1");
    }
    return std::cbrt(18.0 * phi_target / (std::numbers::pi * static_cast<double>(count)));
}

}  // namespace sgmp
