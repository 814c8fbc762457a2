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
    // A file already in a unit (length_scale L₀) is rescaled by L / L₀, so that one
    // control-volume side is L in the new unit; without a new unit it stays as it is.
    const double before = pack.metadata.get_number("length_scale").value_or(1.0);
    const bool rescale = !frame.length_unit.empty();
    const double scale = rescale ? frame.length_scale / before : 1.0;
    Box box = container_box(pack);
    box.lo *= scale;
    box.hi *= scale;
    const bool turned = frame.up == UpAxis::Z;
    if (scale != 1.0 || turned) {
        // The container is always written in the file's unit, so that a reader that
        // takes the box instead (a data file) still finds it after turning back.
        const Container c = container_of(pack);
        const Container scaled{scale * c.x_min, scale * c.x_max, scale * c.z_min, scale * c.z_max,
                               scale * c.floor};
        out.metadata.set("container", scaled.to_string());
        if (const auto y = periodic_y_extent(pack)) {
            out.metadata.set("periodic_y", periodic_y_text(scale * y->first, scale * y->second));
        }
        for (Particle& p : out.particles) {
            p.center *= scale;
            p.radius *= scale;
        }
    }
    if (turned) {
        for (Particle& p : out.particles) {
            p.center = turned_up_z(p.center);
        }
        const Vec3 a = turned_up_z(box.lo), b = turned_up_z(box.hi);
        box = Box{a.cwiseMin(b), a.cwiseMax(b)};
    }
    if (turned || scale != 1.0) {
        out.metadata.set("up_axis", turned ? "z" : "y");
        out.metadata.set("box", box_text(box));
    }
    if (rescale) {
        out.metadata.set_number("length_scale", frame.length_scale);
        out.metadata.set("length_unit", frame.length_unit);
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
