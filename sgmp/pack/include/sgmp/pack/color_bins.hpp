#pragma once
/// @file color_bins.hpp
/// The thesis' ten colour bins (§3.1): `count` particles are shared as evenly as possible
/// among ten bins (bin k holds ⌊N/10⌋ + [k < N mod 10]); particles are then taken one by
/// one from a bin chosen uniformly among the bins that are not yet empty. Colour is only a
/// label; it never changes where a particle goes.
#include <cstddef>
#include <vector>

#include "sgmp/pack/random.hpp"

namespace sgmp {

/// Number of colour bins used by every arrangement.
inline constexpr int kColorBins = 10;

/// Colours 0..9 for `count` particles in drop order, drawn from random non-empty bins.
std::vector<int> draw_colors(std::size_t count, Random& rng);

}  // namespace sgmp
