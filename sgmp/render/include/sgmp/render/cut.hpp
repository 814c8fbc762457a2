#pragma once
/// @file cut.hpp
/// Cut-aways that let the inside of a pack show: spheres whose centre c lies outside
/// the kept slab lo ≤ n·c ≤ hi of a plane with unit normal n are dropped.
///   half:   n is the horizontal direction toward the camera, through the container's
///           vertical axis; the half nearer the camera goes (hi = n·axis, lo = −∞).
///   slice:  the same plane, keeping only |n·c − n·axis| ≤ d (a slab two mean diameters
///           thick, seen face on).
///   x>V, x<V, y>V, y<V, z>V, z<V: the spheres with that coordinate beyond V go.

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"
#include "sgmp/render/view.hpp"

namespace sgmp::render {

/// A cut as typed; resolved into a slab once the view and the pack are known.
struct CutSpec {
    enum class Kind { None, Half, Slice, Axis } kind = Kind::None;
    int axis = 0;         ///< Axis: 0 x, 1 y, 2 z
    bool greater = true;  ///< Axis: drop coordinate > value (else < value)
    double value = 0.0;   ///< Axis: the coordinate of the plane
    std::string text = "none";
};

/// "none", "half", "slice", or "x>V" style (axis x|y|z, '>' or '<', a finite number);
/// nullopt for anything else.
std::optional<CutSpec> parse_cut(std::string_view text);

/// The kept slab lo ≤ n·c ≤ hi.
struct Slab {
    Vec3 normal = Vec3::UnitZ();
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    [[nodiscard]] bool keeps(const Vec3& center) const {
        const double s = normal.dot(center);
        return s >= lo && s <= hi;
    }
};

/// The slab of `spec` for this view, container and mean diameter `d` (file comment).
Slab resolve_cut(const CutSpec& spec, const View& view, const Container& container, double d);

/// Indices of the particles the slab keeps, in order.
std::vector<std::size_t> kept_particles(const std::vector<Particle>& particles, const Slab& slab);

}  // namespace sgmp::render
