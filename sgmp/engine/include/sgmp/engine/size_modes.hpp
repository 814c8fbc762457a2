#pragma once
/// @file size_modes.hpp
/// Multi-modal (polydisperse) sizes, thesis §10.2. A size distribution is a list of modes
/// (relative diameter a_i > 0, number fraction f_i > 0; fractions are normalised). The
/// thesis' sizing rule generalises to (N/3)·(π/6)·Σ f_i (a_i·s)³ = φ*, which fixes the scale
/// s; mode i has diameter a_i·s. One mode of relative size 1 is the monodisperse thesis case
/// (s = d).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sgmp/pack/random.hpp"

namespace sgmp::engine {

struct SizeMode {
    double relative_diameter = 1.0;
    double fraction = 1.0;
};

/// "1:0.7,0.5:0.3" (relative diameter : number fraction, comma separated); nullopt when the
/// text is not of that form or a number is not positive and finite.
std::optional<std::vector<SizeMode>> parse_size_modes(std::string_view text);
std::string size_modes_to_string(const std::vector<SizeMode>& modes);
/// True for the single mode of relative size 1.
bool is_monodisperse(const std::vector<SizeMode>& modes);

/// The scale s: (N/3)·(π/6)·Σ f_i (a_i s)³ = φ* with fractions normalised.
double diameter_scale(std::size_t count, double phi_target, const std::vector<SizeMode>& modes);

/// Diameters of the N particles in drop order: mode counts by the largest-remainder
/// rounding of f_i·N (ties to the earlier mode), order shuffled (Fisher–Yates with `rng`).
/// A monodisperse list draws nothing from `rng`.
std::vector<double> draw_diameters(std::size_t count, double phi_target,
                                   const std::vector<SizeMode>& modes, Random& rng);

}  // namespace sgmp::engine
