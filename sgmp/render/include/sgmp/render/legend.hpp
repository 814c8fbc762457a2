#pragma once
/// @file legend.hpp
/// The picture's key, drawn into the scene in the camera's frame: a colour bar (sequential
/// colourings) or swatches (species), with its caption and tick labels, and a length scale.
///
/// Overlay plane. The key sits on the plane at distance D_o = D/4 in front of the camera
/// (D its distance to the target; the pack's bounding sphere starts beyond 0.74·D), in the
/// strip of normalised screen coordinates u ∈ [1 − 2f, 1], v ∈ [−1, 1] (u right, v up;
/// f = kLegendStrip of the width), where the camera leaves room for it (scene.cpp). A
/// point (u, v) is P = L + D_o·(F + u·tan(a_h)·R + v·tan(a_v)·S), with L the camera, F, R,
/// S its forward, right and up unit vectors, a_h, a_v the half angles.
///
/// Length scale. A bar of n mean diameters d, n the largest of 0.01, 0.02, 0.05, …, 1, 2, 5,
/// 10, … that fits 80 % of the strip, drawn at the size n·d has on the plane through the target
/// facing the camera (the cut face of `--cut half` and `slice`): on the overlay plane
/// n·d·D_o/D (true on the cut face when the view is level, elevation 0). Labelled "n d" and,
/// when the pack has a length unit, "= n·d unit". Text is POV-Ray's `cyrvetic.ttf` (Debian
/// povray-includes), shrunk where a label would pass the image's edge; without the font the
/// key has no labels.
#include <string>
#include <vector>

#include "sgmp/pack/particle.hpp"

namespace sgmp::render {

/// Share of the image width the key takes on the right.
inline constexpr double kLegendStrip = 0.15;

/// The camera frame the key is drawn in.
struct OverlayFrame {
    Vec3 location;
    Vec3 forward;           ///< unit, toward the target
    Vec3 right;             ///< unit, screen right
    Vec3 up;                ///< unit, screen up
    double tan_h = 0.0;     ///< tan of the horizontal half angle
    double tan_v = 0.0;     ///< tan of the vertical half angle
    double distance = 0.0;  ///< camera to target
};

/// What the key says: a sequential colour bar from `lo` to `hi` (viridis, as
/// height_color), or swatches of the first `swatches` qualitative colours; or neither.
struct LegendContent {
    std::vector<std::string> caption;  ///< lines above the bar
    bool bar = false;
    double lo = 0.0;
    double hi = 1.0;
    int swatches = 0;              ///< species 1 … swatches
    double diameter = 0.0;         ///< mean diameter, for the length scale (0: no scale)
    double unit_per_length = 0.0;  ///< file unit per scene length (0: no unit)
    std::string unit;
    /// Whether to write the labels (POV-Ray's font is found: povray.hpp, key_font_found).
    bool text = true;
};

/// POV-Ray text of the key.
std::string legend_scene(const OverlayFrame& frame, const LegendContent& content);

}  // namespace sgmp::render
