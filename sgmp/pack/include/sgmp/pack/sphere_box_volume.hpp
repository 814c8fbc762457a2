#pragma once
/// @file sphere_box_volume.hpp
/// Exact volume of a sphere inside an axis-aligned box.
///
/// V = ∫ A(x) dx over the sphere's slices x ∈ [max(x_lo, cx - r), min(x_hi, cx + r)], where
/// A(x) is the area of the disk of radius ρ(x) = √(r² − (x − cx)²) inside the box's
/// rectangle in (y, z). A(x) is closed form (circular-segment areas combined by
/// inclusion–exclusion over the rectangle's corners). Between the break points where the
/// disk meets an edge line or a corner of the rectangle, A(x) is smooth, with square-root
/// behaviour at the ends; each piece is integrated by tanh–sinh quadrature, which handles
/// such end points to ~1e-15 relative (SphereBoxQuadrature::TanhSinh), or by 32-point
/// Gauss–Legendre after the substitution u = a + (b − a)(1 − cos t)/2 that smooths the
/// square-root ends (SphereBoxQuadrature::GaussLegendre: ~1e-11 of the ball at ~1/25 of the
/// cost, for the many shells of g(r) and slabs of φ(y)). Only spheres that all three axes of
/// the box clip take quadrature: no clip is the ball, one a slab ∫ π(r² − u²) du, two the
/// closed form of ball_cut.hpp. This is the project's one ball-in-box volume.

#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/pack.hpp"

namespace sgmp {

/// How the slices of a sphere that all three axes of the box clip are integrated.
enum class SphereBoxQuadrature {
    TanhSinh,       ///< to ~1e-13 of (4/3)πr³: φ of pack headers, pours and `measure`
    GaussLegendre,  ///< 32 points per piece, ~1e-11 of the ball, ~1/25 of the cost
};

/// Volume of the ball |p - center| ≤ radius inside `box`. The box may be open (infinite
/// bounds). Accurate to ~1e-13 relative to (4/3)πr³ with TanhSinh, ~1e-11 with
/// GaussLegendre (tests/compare/volume_test.cpp).
double sphere_box_volume(const Vec3& center, double radius, const Box& box,
                         SphereBoxQuadrature quadrature = SphereBoxQuadrature::TanhSinh);

/// Packing fraction of `region`: Σ sphere_box_volume(c_i, r_i, region) / |region|, summed
/// in particle order — the one φ of the project (pack headers, pours, `measure`). Throws
/// std::invalid_argument for a region of no volume.
double packing_fraction(const std::vector<Particle>& particles, const Box& region);
/// The same over `pack.particles`.
double packing_fraction(const Pack& pack, const Box& region);

/// Area of the disk of radius `rho` centred at the origin inside [y0, y1] × [z0, z1].
double disk_rectangle_area(double rho, double y0, double y1, double z0, double z1);

}  // namespace sgmp
