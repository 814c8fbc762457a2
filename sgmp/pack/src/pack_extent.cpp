#include "sgmp/pack/pack_extent.hpp"

#include <algorithm>

namespace sgmp {

Container container_of(const Pack& pack) {
    const auto text = pack.metadata.get("container");
    return text ? Container::parse(*text) : Container{};
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
    const Container container = container_of(pack);
    Box box = container.box_up_to(top_of(pack, container));
    for (const auto& p : pack.particles) {
        box.lo = box.lo.cwiseMin(p.center);
        box.hi = box.hi.cwiseMax(p.center);
    }
    return box;
}

}  // namespace sgmp
