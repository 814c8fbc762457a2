#pragma once
#include "sgmp/pack/geometry.hpp"
/// @file ball_cut.hpp
/// Closed-form volume of a ball between two parallel planes and above a third plane
/// perpendicular to them: V = ∫_{u0}^{u1} A_h(x) dx for the unit ball, where A_h(x) is the
/// area of the slice disk (radius s = √(1 − x²)) with y ≥ h,
///     A_h(x) = s² acos(h/s) − h √(s² − h²)   (|x| < c = √(1 − h²)),
/// and 0 or πs² beyond ±c. Its antiderivative, by parts on the acos term, is
///     G(x) = (x − x³/3) acos(h/s) + h[(1/3) I₂ − (2/3) I₀ − I_s] + (2/3) sgn(h) atan(|h| x / √(c²
///     − x²)),
/// with I₀ = asin(x/c), I₂ = (c²/2) asin(x/c) − (x/2)√(c² − x²) and
/// I_s = (x √(c² − x²) + c² asin(x/c))/2. Used for the slabs of φ(y) that one vertical face
/// of the column also cuts, where quadrature would dominate the run time; it agrees with
/// sgmp::sphere_box_volume to ~1e-14 of the ball (tests/compare).

namespace sgmp::compare {

/// Volume of the unit ball with u0 ≤ x ≤ u1 and y ≥ h (any real bounds).
double unit_ball_cut(double u0, double u1, double h);

/// Volume of the ball of radius r (centre at the origin) with x in [x0, x1] and y in [y0, y1].
double ball_cut_volume(double r, double x0, double x1, double y0, double y1);

}  // namespace sgmp::compare

namespace sgmp::compare {

/// Volume of the ball |p − center| ≤ r inside `box`, for g(r) shells: closed form when
/// at most two axes of the box cut the ball (no cut, a slab, or ball_cut_volume); when all
/// three do, the slices along y (disk ∩ rectangle areas, closed form) are integrated with
/// 32-point Gauss–Legendre on each piece between the break points, after the substitution
/// u = a + (b − a)(1 − cos t)/2 that smooths the square-root ends. Agrees with
/// sgmp::sphere_box_volume to ~1e-11 of the ball (tests/compare) at ~1/25 of its cost.
double ball_box_volume(const Vec3& center, double r, const Box& box);

}  // namespace sgmp::compare
