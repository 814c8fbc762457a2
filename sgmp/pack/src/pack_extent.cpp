#include "sgmp/pack/pack_extent.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sgmp/pack/metadata.hpp"

namespace sgmp {

Container container_of(const Pack& pack) {
    const auto text = pack.metadata.get("container");
    Container c = text ? Container::parse(*text) : Container{};
    c.periodic = pack.metadata.get("sides").value_or("walls") == "periodic";
    return c;
}

double top_of(const Pack& pack, const Container& container) {
    if (pack.particles.empty()) {
        return container.floor + (container.x_max - container.x_min);
    }
    double top = container.floor;
    for (const auto& p : pack.particles) {
        top = std::max(top, p.center.y() + p.radius);
    }
    return top;
}

Box container_box(const Pack& pack) {
    if (const auto text = pack.metadata.get("box")) {
        std::istringstream in(*text);
        Box box;
        for (int k = 0; k < 3; ++k) {
            in >> box.lo[k] >> box.hi[k];
        }
        std::string rest;
        if (in.fail() || (in >> rest) || !(box.lo.array() <= box.hi.array()).all() ||
            !box.lo.allFinite() || !box.hi.allFinite()) {
            throw std::invalid_argument("box '" + *text +
                                        "': expected xlo xhi ylo yhi zlo zhi, finite, lo <= hi");
        }
        return box;
    }
    const Container container = container_of(pack);
    Box box = container.box_up_to(top_of(pack, container));
    if (const auto y = periodic_y_extent(pack)) {
        box.lo.y() = y->first;
        box.hi.y() = y->second;
    }
    for (const auto& p : pack.particles) {
        box.lo = box.lo.cwiseMin(p.center);
        box.hi = box.hi.cwiseMax(p.center);
    }
    return box;
}

std::array<bool, 3> periodic_axes(const Pack& pack) {
    if (!container_of(pack).periodic) {
        return {false, false, false};
    }
    if (pack.metadata.contains("periodic_y")) {
        return {true, true, true};  // a fully periodic cell
    }
    const bool z_up = pack.metadata.get("up_axis").value_or("y") == "z";
    return {true, z_up, !z_up};
}

std::optional<std::pair<double, double>> periodic_y_extent(const Pack& pack) {
    const auto text = pack.metadata.get("periodic_y");
    if (!text) {
        return std::nullopt;
    }
    std::istringstream in(*text);
    double lo = 0.0;
    double hi = 0.0;
    std::string rest;
    in >> lo >> hi;
    if (in.fail() || (in >> rest) || !std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) {
        throw std::invalid_argument("periodic_y '" + *text +
                                    "': expected 'ylo yhi', finite, lo < hi");
    }
    return std::pair{lo, hi};
}

std::string periodic_y_text(double lo, double hi) {
    return format_number(lo) + ' ' + format_number(hi);
}

}  // namespace sgmp
