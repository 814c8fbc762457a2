#include "sgmp/render/cut.hpp"

#include <charconv>
#include <cmath>

namespace sgmp::render {

std::optional<CutSpec> parse_cut(std::string_view text) {
    CutSpec spec;
    spec.text = std::string(text);
    if (text == "none") {
        return spec;
    }
    if (text == "half") {
        spec.kind = CutSpec::Kind::Half;
        return spec;
    }
    if (text == "slice") {
        spec.kind = CutSpec::Kind::Slice;
        return spec;
    }
    if (text.size() < 3 || (text[1] != '>' && text[1] != '<')) {
        return std::nullopt;
    }
    const auto axis = std::string_view("xyz").find(text[0]);
    if (axis == std::string_view::npos) {
        return std::nullopt;
    }
    const auto value_text = text.substr(2);
    const auto* end = value_text.data() + value_text.size();
    const auto [ptr, ec] = std::from_chars(value_text.data(), end, spec.value);
    if (ec != std::errc() || ptr != end || !std::isfinite(spec.value)) {
        return std::nullopt;
    }
    spec.kind = CutSpec::Kind::Axis;
    spec.axis = static_cast<int>(axis);
    spec.greater = text[1] == '>';
    return spec;
}

Slab resolve_cut(const CutSpec& spec, const View& view, const Container& container, double d) {
    Slab slab;
    const Vec3 axis_point(0.5 * (container.x_min + container.x_max), 0.0,
                          0.5 * (container.z_min + container.z_max));
    switch (spec.kind) {
        case CutSpec::Kind::None:
            break;
        case CutSpec::Kind::Half:
            slab.normal = horizontal_toward_camera(view);
            slab.hi = slab.normal.dot(axis_point);
            break;
        case CutSpec::Kind::Slice:
            slab.normal = horizontal_toward_camera(view);
            slab.lo = slab.normal.dot(axis_point) - d;
            slab.hi = slab.normal.dot(axis_point) + d;
            break;
        case CutSpec::Kind::Axis:
            // Keep n·c ≤ hi: for "x>V" n = +x, hi = V; for "x<V" n = −x, hi = −V.
            slab.normal = Vec3::Zero();
            slab.normal[spec.axis] = spec.greater ? 1.0 : -1.0;
            slab.hi = spec.greater ? spec.value : -spec.value;
            break;
    }
    return slab;
}

std::vector<std::size_t> kept_particles(const std::vector<Particle>& particles, const Slab& slab) {
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        if (slab.keeps(particles[i].center)) {
            kept.push_back(i);
        }
    }
    return kept;
}

}  // namespace sgmp::render
