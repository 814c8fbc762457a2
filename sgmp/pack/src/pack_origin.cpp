#include "sgmp/pack/pack_origin.hpp"

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/metadata.hpp"

namespace sgmp {

Vec3 move_corner_to_origin(Pack& pack) {
    const auto text = pack.metadata.get("container");
    const Container c = text ? Container::parse(*text) : Container{};
    const Vec3 shift(-c.x_min, -c.floor, -c.z_min);
    for (Particle& p : pack.particles) {
        p.center += shift;
    }
    const Container moved{0.0, c.x_max - c.x_min, 0.0, c.z_max - c.z_min, 0.0};
    pack.metadata.set("container", moved.to_string());
    pack.metadata.set("origin_shift", format_number(shift.x()) + " " + format_number(shift.y()) +
                                          " " + format_number(shift.z()));
    return shift;
}

}  // namespace sgmp
