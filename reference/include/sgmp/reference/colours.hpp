#pragma once
/// @file colours.hpp
/// Colour labels (thesis 3.1): ten bins holding N/10 particles each (the first N mod 10
/// bins one more); each particle in turn takes a random non-empty bin.

#include <vector>

#include "sgmp/pack/particle.hpp"
#include "sgmp/pack/random.hpp"

namespace sgmp::reference {

inline constexpr int kColourBins = 10;

void assign_colours(std::vector<Particle>& particles, Random& random);

}  // namespace sgmp::reference
