#pragma once
/// @file palette.hpp
/// Colours of the spheres: a fixed qualitative palette for the colour bins and a
/// sequential one (viridis) for heights. Colours are sRGB in [0, 1]; the scene converts
/// them to linear light, c = ((s + 0.055)/1.055)^2.4 (s > 0.04045), else s/12.92.

#include <array>

namespace sgmp::render {

struct Rgb {
    double r = 0.0;
    double g = 0.0;
    double b = 0.0;
};

/// Number of colours of the qualitative palette (the colour bins 0–9).
inline constexpr int kBinColors = 10;

/// The qualitative colour of bin `bin` (Tableau 10); bins outside [0, 10) wrap around.
Rgb bin_color(int bin);

/// The sequential colour at t ∈ [0, 1] (viridis, piecewise linear between 9 stops);
/// t outside [0, 1] is clamped.
Rgb height_color(double t);

/// sRGB → linear light (the formula in the file comment), per channel.
Rgb linear_from_srgb(const Rgb& color);

}  // namespace sgmp::render
