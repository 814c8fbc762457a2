#pragma once
/// @file scene.hpp
/// A pack as a POV-Ray scene: shaded spheres coloured by colour bin, height or species, the
/// container as a thin outline or translucent walls, a camera from azimuth and elevation
/// that fits the container up to the pack's top, and an optional cut-away (cut.hpp).
/// Pure text: the same pack and options give the same bytes.
///
/// Axes are the testbed's (right-handed, Y up); the camera's `right` vector is mirrored so
/// POV-Ray's left-handed frame shows the pack unmirrored.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sgmp/pack/pack.hpp"
#include "sgmp/render/cut.hpp"
#include "sgmp/render/view.hpp"

namespace sgmp::render {

/// Sphere colours: the colour bin (Tableau 10), the height (viridis from the floor to the
/// top), the species of a blend (Tableau 10 in species order: 1 blue, 2 orange, 3 green…),
/// or one value per sphere given by the caller (viridis from its least to its largest
/// finite value; grey where it is NaN), such as the coordination or the local φ.
enum class Coloring { Bin, Height, Species, Values };
enum class ContainerStyle { Outline, Walls, None };

struct SceneOptions {
    int width = 800;  ///< pixels (only the aspect ratio enters the scene)
    int height = 800;
    View view;
    Coloring coloring = Coloring::Bin;
    ContainerStyle container = ContainerStyle::Outline;
    CutSpec cut;
    /// Coloring::Values: one value per particle, and the key's caption lines.
    std::vector<double> values;
    std::vector<std::string> caption;
    /// The colour range of the values: from the q to the 1 − q quantile of the finite
    /// values (beyond it the end colours), q = clip_quantile; 0: least to largest.
    double clip_quantile = 0.0;
    /// A colour range fixed by the caller, [lo, hi] with hi > lo (beyond it the end colours),
    /// so that several pictures share one scale; it overrides clip_quantile.
    std::optional<std::pair<double, double>> value_limits;
    /// Draw the key (legend.hpp): the colour bar or species swatches and a length scale,
    /// in a strip on the right of the image.
    bool legend = true;
    /// Whether the key has its labels: POV-Ray's font was found (povray.hpp).
    bool key_text = true;
    /// Free text placed in the scene's first comment lines (what made it).
    std::string provenance;
};

/// Parses "bin" | "height" | "species" (values come from the caller), and "outline" |
/// "walls" | "none".
std::optional<Coloring> parse_coloring(std::string_view text);
std::optional<ContainerStyle> parse_container_style(std::string_view text);

/// The scene text. The container is the pack's `container` header key (the thesis
/// container when absent). Throws std::invalid_argument for a malformed container key, a
/// pack without particles, or Coloring::Values without one value per particle.
std::string povray_scene(const Pack& pack, const SceneOptions& options);

/// Number of spheres in a scene text (lines starting "sphere{"), for checks.
std::size_t scene_sphere_count(const std::string& scene);

}  // namespace sgmp::render
