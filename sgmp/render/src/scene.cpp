#include "sgmp/render/scene.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "sgmp/pack/pack_extent.hpp"
#include "sgmp/pack/version.hpp"
#include "sgmp/render/legend.hpp"
#include "sgmp/render/palette.hpp"

namespace sgmp::render {
namespace {

/// Vertical half field of view of the camera.
constexpr double kHalfAngleDegrees = 15.0;

std::string num(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.6f", value == 0.0 ? 0.0 : value);  // no "-0.000000"
    return text;
}

std::string vec(const Vec3& v) {
    return "<" + num(v.x()) + "," + num(v.y()) + "," + num(v.z()) + ">";
}

std::string rgb(const Rgb& srgb) {
    const Rgb c = linear_from_srgb(srgb);
    return "rgb <" + num(c.r) + "," + num(c.g) + "," + num(c.b) + ">";
}

double top_of(const std::vector<Particle>& particles, const Container& container) {
    double top = container.floor;
    for (const Particle& p : particles) {
        top = std::max(top, p.center.y() + p.radius);
    }
    return top;
}

/// The camera and its frame: location, target, sky (image up) and right.
struct Camera {
    Vec3 location;
    Vec3 target;
    Vec3 sky;
    Vec3 right;
    double horizontal_angle = 0.0;  // full, degrees
    double pixel = 0.0;             // length of one pixel at the target
};

/// Fits the bounding sphere of `box` (radius R) into the frame: distance R / sin(a), a the
/// smaller half angle of the frame. With the key, the pack is fitted into the left
/// 1 − f of the width (half angle atan((1 − f)·tan a_h)) and the camera and its target
/// move by f·tan(a_h)·D along `right`, so the box's centre shows at u = −f.
Camera fit_camera(const Box& box, const SceneOptions& o) {
    Camera c;
    c.target = 0.5 * (box.lo + box.hi);
    const double radius = 0.5 * (box.hi - box.lo).norm();
    const double aspect = static_cast<double>(o.width) / static_cast<double>(o.height);
    const double a_v = kHalfAngleDegrees * std::numbers::pi / 180.0;
    const double a_h = std::atan(std::tan(a_v) * aspect);
    const double strip = o.legend ? kLegendStrip : 0.0;
    const double a_fit = std::atan((1.0 - strip) * std::tan(a_h));
    const double distance = radius / std::sin(std::min(a_v, a_fit));
    const Vec3 u = toward_camera(o.view);
    // Straight above or below, "up" in the image is away from the camera's horizontal side.
    c.sky = std::abs(o.view.elevation) > 89.0 ? Vec3(-horizontal_toward_camera(o.view))
                                              : Vec3(Vec3::UnitY());
    c.right = (-u).cross(c.sky).normalized();
    c.target += strip * std::tan(a_h) * distance * c.right;
    c.location = c.target + distance * u;
    c.horizontal_angle = 2.0 * a_h * 180.0 / std::numbers::pi;
    c.pixel = 2.0 * distance * std::tan(a_v) / static_cast<double>(o.height);
    return c;
}

/// The camera's frame for the key.
OverlayFrame overlay_frame(const Camera& c, const SceneOptions& o) {
    OverlayFrame f;
    f.location = c.location;
    f.distance = (c.target - c.location).norm();
    f.forward = (c.target - c.location) / f.distance;
    f.right = c.right;
    f.up = f.right.cross(f.forward).normalized();
    const double aspect = static_cast<double>(o.width) / static_cast<double>(o.height);
    f.tan_v = std::tan(kHalfAngleDegrees * std::numbers::pi / 180.0);
    f.tan_h = f.tan_v * aspect;
    return f;
}

/// The colour range of the caller's values: the range the caller fixed, else the q and
/// 1 − q quantiles (nearest rank) of the finite ones, [lo, hi] with hi > lo.
std::pair<double, double> value_range(const std::vector<double>& values, double q,
                                      const std::optional<std::pair<double, double>>& fixed) {
    if (fixed) {
        if (!std::isfinite(fixed->first) || !std::isfinite(fixed->second) ||
            fixed->second <= fixed->first) {
            throw std::invalid_argument("the fixed colour range must be finite with hi > lo");
        }
        return *fixed;
    }
    std::vector<double> finite;
    for (const double v : values) {
        if (std::isfinite(v)) {
            finite.push_back(v);
        }
    }
    if (finite.empty()) {
        return {0.0, 1.0};
    }
    std::sort(finite.begin(), finite.end());
    const auto rank = [&](double p) {
        return finite[static_cast<std::size_t>(
            std::lround(p * static_cast<double>(finite.size() - 1)))];
    };
    const double lo = rank(q), hi = rank(1.0 - q);
    return {lo, hi > lo ? hi : lo + 1.0};
}

/// What the key shows for these options.
LegendContent legend_content(const Pack& pack, const SceneOptions& o, double floor, double top) {
    LegendContent c;
    c.text = o.key_text;
    const double d = mean_diameter(pack);
    c.diameter = d;
    if (const auto unit = pack.metadata.get("length_unit");
        unit && pack.metadata.contains("length_scale")) {
        c.unit = *unit;
        c.unit_per_length = 1.0;  // lengths are read in the file's unit
    }
    if (o.coloring == Coloring::Height) {
        c.caption = {"height", "above floor"};
        c.bar = true;
        c.lo = 0.0;
        c.hi = d > 0.0 ? (top - floor) / d : 1.0;
        c.caption.back() += ", d";
    } else if (o.coloring == Coloring::Values) {
        c.caption = o.caption;
        c.bar = true;
        std::tie(c.lo, c.hi) = value_range(o.values, o.clip_quantile, o.value_limits);
    } else if (o.coloring == Coloring::Species) {
        c.caption = {"species"};
        int species = 1;
        for (const Particle& p : pack.particles) {
            species = std::max(species, p.species);
        }
        c.swatches = species;
    }
    return c;
}

void write_header(std::ostream& out, const Pack& pack, const SceneOptions& o, std::size_t kept) {
    out << "// POV-Ray 3.7 scene of a pack, made by sgmp render " << sgmp::version() << "\n";
    std::istringstream lines(o.provenance);
    for (std::string line; std::getline(lines, line);) {
        out << "// " << line << "\n";
    }
    out << "// spheres: " << kept << " of " << pack.particles.size() << " (cut " << o.cut.text
        << ")\n";
    out << "#version 3.7;\n"
        << "global_settings { assumed_gamma 1.0 max_trace_level 8 }\n"
        << "background { color rgb <1,1,1> }\n";
}

void write_camera(std::ostream& out, const Camera& c, const SceneOptions& o) {
    const double aspect = static_cast<double>(o.width) / static_cast<double>(o.height);
    // right is mirrored (-x): the testbed's right-handed axes in POV-Ray's left-handed frame.
    out << "camera { perspective location " << vec(c.location) << " sky " << vec(c.sky)
        << " up y right -x*" << num(aspect) << " angle " << num(c.horizontal_angle) << " look_at "
        << vec(c.target) << " }\n";
    const Vec3 u = (c.location - c.target).normalized();
    const double distance = (c.location - c.target).norm();
    const Vec3 key = c.target + 2.0 * distance * (u + 0.9 * c.sky - 0.6 * c.right).normalized();
    out << "light_source { " << vec(key) << " color rgb <1,1,1> }\n"
        << "light_source { " << vec(c.location) << " color rgb <0.35,0.35,0.35> shadowless }\n";
}

void write_outline(std::ostream& out, const Box& box, double radius) {
    out << "#declare Edge = texture { pigment { color rgb <0.05,0.05,0.05> } finish { ambient 1 "
           "diffuse 0 } }\n";
    const double xs[2] = {box.lo.x(), box.hi.x()};
    const double ys[2] = {box.lo.y(), box.hi.y()};
    const double zs[2] = {box.lo.z(), box.hi.z()};
    auto edge = [&](const Vec3& a, const Vec3& b) {
        out << "cylinder { " << vec(a) << "," << vec(b) << "," << num(radius)
            << " texture { Edge } no_shadow }\n";
    };
    for (const double y : ys) {
        for (const double z : zs) {
            edge(Vec3(xs[0], y, z), Vec3(xs[1], y, z));
        }
        for (const double x : xs) {
            edge(Vec3(x, y, zs[0]), Vec3(x, y, zs[1]));
        }
    }
    for (const double x : xs) {
        for (const double z : zs) {
            edge(Vec3(x, ys[0], z), Vec3(x, ys[1], z));
        }
    }
}

/// The floor and the walls on the far side of the camera, translucent.
void write_walls(std::ostream& out, const Box& box, const View& view, double thickness) {
    out << "#declare Wall = texture { pigment { color rgbt <0.80,0.84,0.90,0.55> } finish { "
           "ambient 0.3 diffuse 0.6 } }\n";
    const Vec3 h = horizontal_toward_camera(view);
    auto slab = [&](const Vec3& lo, const Vec3& hi) {
        out << "box { " << vec(lo) << "," << vec(hi) << " texture { Wall } no_shadow }\n";
    };
    const Vec3& lo = box.lo;
    const Vec3& hi = box.hi;
    slab(Vec3(lo.x(), lo.y() - thickness, lo.z()), Vec3(hi.x(), lo.y(), hi.z()));
    if (h.x() >= 0.0) {  // the wall at x_min faces away from the camera
        slab(Vec3(lo.x() - thickness, lo.y(), lo.z()), Vec3(lo.x(), hi.y(), hi.z()));
    }
    if (h.x() <= 0.0) {
        slab(Vec3(hi.x(), lo.y(), lo.z()), Vec3(hi.x() + thickness, hi.y(), hi.z()));
    }
    if (h.z() >= 0.0) {
        slab(Vec3(lo.x(), lo.y(), lo.z() - thickness), Vec3(hi.x(), hi.y(), lo.z()));
    }
    if (h.z() <= 0.0) {
        slab(Vec3(lo.x(), lo.y(), hi.z()), Vec3(hi.x(), hi.y(), hi.z() + thickness));
    }
}

void write_spheres(std::ostream& out, const Pack& pack, const std::vector<std::size_t>& kept,
                   const SceneOptions& o, double floor, double top) {
    out << "#declare Shade = finish { ambient 0.10 diffuse 0.75 specular 0.35 roughness 0.015 "
           "}\n";
    const auto [lo, hi] = value_range(o.values, o.clip_quantile, o.value_limits);
    if (o.coloring == Coloring::Bin || o.coloring == Coloring::Species) {
        for (int bin = 0; bin < kBinColors; ++bin) {
            out << "#declare Bin" << bin << " = texture { pigment { color " << rgb(bin_color(bin))
                << " } finish { Shade } }\n";
        }
    }
    const double span = top > floor ? top - floor : 1.0;
    for (const std::size_t i : kept) {
        const Particle& p = pack.particles[i];
        out << "sphere{" << vec(p.center) << "," << num(p.radius) << " texture{";
        if (o.coloring == Coloring::Bin) {
            out << "Bin" << ((p.color % kBinColors) + kBinColors) % kBinColors;
        } else if (o.coloring == Coloring::Species) {
            // Species 1, 2, … take the palette's colours in order (a pack without species
            // is all species 1).
            const int species = std::max(p.species, 1) - 1;
            out << "Bin" << species % kBinColors;
        } else if (o.coloring == Coloring::Values) {
            const double v = i < o.values.size() ? o.values[i] : NAN;
            out << "pigment{color "
                << (std::isfinite(v) ? rgb(height_color((v - lo) / (hi - lo)))
                                     : rgb(Rgb{0.75, 0.75, 0.75}))
                << "} finish{Shade}";
        } else {
            out << "pigment{color " << rgb(height_color((p.center.y() - floor) / span))
                << "} finish{Shade}";
        }
        out << "}}\n";
    }
}

}  // namespace

std::optional<Coloring> parse_coloring(std::string_view text) {
    if (text == "bin") {
        return Coloring::Bin;
    }
    if (text == "height") {
        return Coloring::Height;
    }
    if (text == "species") {
        return Coloring::Species;
    }
    return std::nullopt;
}

std::optional<ContainerStyle> parse_container_style(std::string_view text) {
    if (text == "outline") {
        return ContainerStyle::Outline;
    }
    if (text == "walls") {
        return ContainerStyle::Walls;
    }
    if (text == "none") {
        return ContainerStyle::None;
    }
    return std::nullopt;
}

std::string povray_scene(const Pack& pack, const SceneOptions& o) {
    if (pack.particles.empty()) {
        throw std::invalid_argument("the pack has no particles");
    }
    if (o.coloring == Coloring::Values && o.values.size() != pack.particles.size()) {
        throw std::invalid_argument("colour values: " + std::to_string(o.values.size()) + " for " +
                                    std::to_string(pack.particles.size()) + " spheres");
    }
    const Container container = container_of(pack);
    const double top = top_of(pack.particles, container);
    const Box box = container.box_up_to(std::max(top, container.floor + 1e-3));
    const Slab slab = resolve_cut(o.cut, o.view, container, mean_diameter(pack));
    const auto kept = kept_particles(pack.particles, slab);
    const Camera camera = fit_camera(box, o);
    std::ostringstream out;
    write_header(out, pack, o, kept.size());
    write_camera(out, camera, o);
    if (o.container == ContainerStyle::Outline) {
        write_outline(out, box, 0.8 * camera.pixel);
    } else if (o.container == ContainerStyle::Walls) {
        write_walls(out, box, o.view, 2.0 * camera.pixel);
    }
    write_spheres(out, pack, kept, o, container.floor, top);
    if (o.legend) {
        out << legend_scene(overlay_frame(camera, o),
                            legend_content(pack, o, container.floor, top));
    }
    return out.str();
}

std::size_t scene_sphere_count(const std::string& scene) {
    std::size_t count = 0;
    std::istringstream lines(scene);
    for (std::string line; std::getline(lines, line);) {
        count += line.rfind("sphere{", 0) == 0 ? 1 : 0;
    }
    return count;
}

}  // namespace sgmp::render
