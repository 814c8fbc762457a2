#include "sgmp/render/legend.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "sgmp/render/palette.hpp"

namespace sgmp::render {
namespace {

/// Text height, in units of the frame's half height (v).
constexpr double kTextHeight = 0.055;
/// Segments of the colour bar.
constexpr int kBarSegments = 48;

std::string num(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.6f", value == 0.0 ? 0.0 : value);
    return text;
}

std::string vec(const Vec3& v) {
    return "<" + num(v.x()) + "," + num(v.y()) + "," + num(v.z()) + ">";
}

std::string tick(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.3g", value == 0.0 ? 0.0 : value);
    return text;
}

/// Escapes a string for a POV-Ray string literal.
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
        }
        out += c;
    }
    return out + "\"";
}

class Overlay {
  public:
    Overlay(const OverlayFrame& f, bool with_text)
        : f_(f), depth_(0.25 * f.distance), with_text_(with_text) {}

    /// The overlay point at screen (u, v).
    [[nodiscard]] Vec3 at(double u, double v) const {
        return f_.location + depth_ * (f_.forward + u * f_.tan_h * f_.right + v * f_.tan_v * f_.up);
    }
    /// World length of one unit of v on the overlay plane.
    [[nodiscard]] double v_unit() const { return depth_ * f_.tan_v; }
    /// World length of one unit of u on the overlay plane.
    [[nodiscard]] double u_unit() const { return depth_ * f_.tan_h; }

    /// A flat rectangle [u0, u1] × [v0, v1] of `colour` (a POV-Ray colour expression), as
    /// two triangles (a polygon's corners, printed to 6 decimals, may miss their plane).
    void rectangle(std::ostream& out, double u0, double v0, double u1, double v1,
                   const std::string& colour) const {
        const Vec3 a = at(u0, v0), b = at(u1, v0), c = at(u1, v1), d = at(u0, v1);
        out << "mesh { triangle { " << vec(a) << "," << vec(b) << "," << vec(c) << " } triangle { "
            << vec(a) << "," << vec(c) << "," << vec(d) << " } texture { pigment { color " << colour
            << " } finish { ambient 1 diffuse 0 } } no_shadow }\n";
    }

    /// `text` with its baseline's left end at (u, v), `size` units of v high, smaller where
    /// it would pass the image's right edge (a glyph is taken as 0.6 of its height wide).
    void label(std::ostream& out, double u, double v, const std::string& text,
               double size = kTextHeight) const {
        if (!with_text_) {
            return;
        }
        const double room = (0.98 - u) * u_unit();  // world width left to the edge
        const double wide = 0.6 * static_cast<double>(text.size()) * size * v_unit();
        const double s = size * v_unit() * (wide > room && wide > 0.0 ? room / wide : 1.0);
        const Vec3 r = s * f_.right, up = s * f_.up, z = 0.01 * s * f_.forward;
        const Vec3 o = at(u, v);
        out << "text { ttf \"cyrvetic.ttf\" " << quoted(text)
            << " 1, 0 texture { Ink } no_shadow matrix <" << num(r.x()) << "," << num(r.y()) << ","
            << num(r.z()) << ", " << num(up.x()) << "," << num(up.y()) << "," << num(up.z()) << ", "
            << num(z.x()) << "," << num(z.y()) << "," << num(z.z()) << ", " << num(o.x()) << ","
            << num(o.y()) << "," << num(o.z()) << "> }\n";
    }

  private:
    OverlayFrame f_;
    double depth_;
    bool with_text_;
};

std::string colour_of(const Rgb& srgb) {
    const Rgb c = linear_from_srgb(srgb);
    return "rgb <" + num(c.r) + "," + num(c.g) + "," + num(c.b) + ">";
}

void write_bar(std::ostream& out, const Overlay& o, const LegendContent& c, double u0,
               double width) {
    const double lo_v = -0.45, hi_v = 0.45;
    const double bar_u0 = u0 + 0.08 * width, bar_u1 = u0 + 0.22 * width;
    for (int k = 0; k < kBarSegments; ++k) {
        const double t0 = static_cast<double>(k) / kBarSegments;
        const double t1 = static_cast<double>(k + 1) / kBarSegments;
        o.rectangle(out, bar_u0, lo_v + t0 * (hi_v - lo_v), bar_u1, lo_v + t1 * (hi_v - lo_v),
                    colour_of(height_color(0.5 * (t0 + t1))));
    }
    for (const double t : {0.0, 0.5, 1.0}) {
        const double v = lo_v + t * (hi_v - lo_v);
        o.rectangle(out, bar_u1, v - 0.002, bar_u1 + 0.04 * width, v + 0.002, "rgb <0,0,0>");
        o.label(out, bar_u1 + 0.08 * width, v - 0.35 * kTextHeight, tick(c.lo + t * (c.hi - c.lo)));
    }
}

void write_swatches(std::ostream& out, const Overlay& o, const LegendContent& c, double u0,
                    double width) {
    const int n = std::min(c.swatches, kBinColors);
    for (int k = 0; k < n; ++k) {
        const double v = 0.45 - 0.1 * k;
        o.rectangle(out, u0 + 0.08 * width, v - 0.03, u0 + 0.22 * width, v + 0.03,
                    colour_of(bin_color(k)));
        o.label(out, u0 + 0.3 * width, v - 0.35 * kTextHeight, std::to_string(k + 1));
    }
}

void write_scale(std::ostream& out, const Overlay& o, const OverlayFrame& f, const LegendContent& c,
                 double u0, double width) {
    // n·d on the target plane is n·d·D_o/D on the overlay plane: in units of u,
    // n·d / (D·tan a_h).
    const double per_diameter = c.diameter / (f.distance * f.tan_h);
    double n = 0.01;
    for (double step = 0.01; step < 1e6; step *= 10.0) {
        for (const double m : {1.0, 2.0, 5.0}) {
            if (m * step * per_diameter <= 0.8 * width) {
                n = m * step;
            }
        }
    }
    const double u_start = u0 + 0.08 * width;
    o.rectangle(out, u_start, -0.80, u_start + n * per_diameter, -0.785, "rgb <0,0,0>");
    o.label(out, u_start, -0.88, tick(n) + " d");
    if (c.unit_per_length > 0.0 && !c.unit.empty()) {
        o.label(out, u_start, -0.95, "= " + tick(n * c.diameter * c.unit_per_length) + " " + c.unit,
                0.8 * kTextHeight);
    }
}

}  // namespace

std::string legend_scene(const OverlayFrame& frame, const LegendContent& content) {
    std::ostringstream out;
    out << "#declare Ink = texture { pigment { color rgb <0,0,0> } finish { ambient 1 diffuse 0 "
           "} }\n";
    const Overlay o(frame, content.text);
    const double width = 2.0 * kLegendStrip;  // of u
    const double u0 = 1.0 - width;
    double v = 0.62;
    for (std::size_t line = 0; line < content.caption.size(); ++line) {
        o.label(out, u0 + 0.04 * width, v, content.caption[line],
                line == 0 ? kTextHeight : 0.8 * kTextHeight);
        v -= 1.3 * kTextHeight;
    }
    if (content.bar) {
        write_bar(out, o, content, u0, width);
    } else if (content.swatches > 0) {
        write_swatches(out, o, content, u0, width);
    }
    if (content.diameter > 0.0) {
        write_scale(out, o, frame, content, u0, width);
    }
    return out.str();
}

}  // namespace sgmp::render
