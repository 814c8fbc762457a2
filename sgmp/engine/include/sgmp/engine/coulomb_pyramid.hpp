#pragma once
/// @file coulomb_pyramid.hpp
/// The pyramid that stands for a Coulomb cone in the linear programs of the frictional
/// settling and the frictional certificate. Around the unit normal n of a contact, with
/// t₁ = n × h/|n × h| (h = x̂, or ŷ when |nₓ| ≥ 0.9) and t₂ = n × t₁, its 8 edges are
///
///     Eₖ = n + μ'·(cos θₖ·t₁ + sin θₖ·t₂),   θₖ = 2πk/8,   μ' = μ·cos(π/8),
///
/// so the pyramid {Σₖ βₖ·Eₖ : βₖ ≥ 0} lies inside the cone |f_t| ≤ μ·f_n (its facets touch
/// the cone), and any force it holds obeys Coulomb's law. Each edge has n·Eₖ = 1: the normal
/// part of Σₖ βₖ·Eₖ is Σₖ βₖ. The set of edges is the same for −n (the directions are
/// multiples of 45° either way), so either sphere of a pair may name the normal.
#include <array>

#include "sgmp/pack/particle.hpp"

namespace sgmp::engine {

inline constexpr int kPyramidEdges = 8;

/// The edges Eₖ of the pyramid around `normal` (a unit vector) at sliding friction μ ≥ 0.
std::array<Vec3, kPyramidEdges> coulomb_pyramid(const Vec3& normal, double friction);

/// The friction μ·cos²(π/8) of the widest circular cone inside the pyramid at μ (its facets
/// lie μ'·cos(π/8) from the normal): a force in that cone is a sum of the pyramid's edges.
double pyramid_inscribed_friction(double friction);

}  // namespace sgmp::engine
