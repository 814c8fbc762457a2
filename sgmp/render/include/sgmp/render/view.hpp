#pragma once
/// @file view.hpp
/// Where the camera looks from. Azimuth φ is measured about the vertical Y axis from +Z
/// toward +X, elevation θ above the horizontal plane, both in degrees; the unit vector
/// from the pack toward the camera is u = (cos θ sin φ, sin θ, cos θ cos φ).

#include <optional>
#include <string_view>

#include "sgmp/pack/particle.hpp"

namespace sgmp::render {

struct View {
    double azimuth = 35.0;    ///< degrees, any value
    double elevation = 30.0;  ///< degrees, in [-90, 90]
};

/// "AZ,EL" (degrees; EL in [-90, 90]) or a preset: front (0,10), top (0,90), iso (35,30).
/// nullopt for anything else.
std::optional<View> parse_view(std::string_view text);

/// u above: the unit vector from the target toward the camera.
Vec3 toward_camera(const View& view);

/// The unit horizontal direction toward the camera, (sin φ, 0, cos φ); defined for every
/// elevation, so a view from straight above still has a front.
Vec3 horizontal_toward_camera(const View& view);

}  // namespace sgmp::render
