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

/// Non-negative edge multipliers β with Σₖ βₖ·Eₖ = f·n + f_t (f ≥ 0 the normal force, f_t
/// the force across `normal`, its normal part ignored): with f_t/μ' = a·uₖ + b·uₖ₊₁ over the
/// two edge directions uₖ = (Eₖ − n)/μ' either side of f_t (a, b ≥ 0), βⱼ = (f − a − b)/8
/// plus a on edge k and b on edge k + 1, exact while a + b ≤ f (f_t inside the pyramid);
/// beyond it a and b are scaled to a + b = f (the nearest force the pyramid holds along
/// f_t). At μ = 0 f_t is dropped. f < 0 gives all zeros.
std::array<double, kPyramidEdges> pyramid_edge_forces(const Vec3& normal, double friction,
                                                      double normal_force, const Vec3& tangential);

}  // namespace sgmp::engine
