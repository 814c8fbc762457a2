#include "sgmp/pack/output_frame.hpp"

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/pack_extent.hpp"

namespace sgmp {

namespace {

/// R·c for up = z: (x, y, z) → (x, −z, y).
Vec3 turned_up_z(const Vec3& c) {
    return {c.x(), -c.z(), c.y()};
}

std::string box_text(const Box& box) {
    std::string text;
    for (int k = 0; k < 3; ++k) {
        text += (k ? " " : "") + format_number(box.lo[k]) + " " + format_number(box.hi[k]);
    }
    return text;
}

}  // namespace

Pack in_output_frame(const Pack& pack, const OutputFrame& frame) {
    Pack out = pack;
    const double scale = frame.length_scale;
    Box box = container_box(pack);
    box.lo *= scale;
    box.hi *= scale;
    if (scale != 1.0) {
        const Container c = container_of(pack);
        const Container scaled{scale * c.x_min, scale * c.x_max, scale * c.z_min, scale * c.z_max,
                               scale * c.floor};
        out.metadata.set("container", scaled.to_string());
        for (Particle& p : out.particles) {
            p.center *= scale;
            p.radius *= scale;
        }
    }
    if (frame.up == UpAxis::Z) {
        for (Particle& p : out.particles) {
            p.center = turned_up_z(p.center);
        }
        const Vec3 a = turned_up_z(box.lo), b = turned_up_z(box.hi);
        box = Box{a.cwiseMin(b), a.cwiseMax(b)};
    }
    if (frame.up == UpAxis::Z || scale != 1.0) {
        out.metadata.set("up_axis", frame.up == UpAxis::Z ? "z" : "y");
        out.metadata.set("box", box_text(box));
    }
    if (scale != 1.0 || !frame.length_unit.empty()) {
        out.metadata.set_number("length_scale", scale);
        out.metadata.set("length_unit",
                         frame.length_unit.empty() ? "control-volume side" : frame.length_unit);
    }
    if (frame.density) {
        out.metadata.set_number("particle_density", *frame.density);
    }
    return out;
}

void to_internal_frame(Pack& pack) {
    const auto up = pack.metadata.get("up_axis");
    if (up && *up == "z") {
        for (Particle& p : pack.particles) {
            p.center = Vec3(p.center.x(), p.center.z(), -p.center.y());
        }
        pack.metadata.set("up_axis", "y");
    }
    pack.metadata.erase("box");
}

}  // namespace sgmp
