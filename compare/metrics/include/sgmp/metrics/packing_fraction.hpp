#pragma once
/// @file packing_fraction.hpp
/// Exact packing fraction of a box region and its profile in horizontal slabs:
///     φ(B) = Σ_i V(ball_i ∩ B) / |B|,
/// with V from sgmp::sphere_box_volume (closed form when one axis clips the ball,
/// tanh–sinh quadrature otherwise). Works for any radii. φ(B) itself is the pack
/// library's sgmp::packing_fraction (sgmp/pack/sphere_box_volume.hpp), the one φ.

#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::metrics {

/// φ in horizontal slabs [y0 + k·t, y0 + (k+1)·t] ∩ [y0, y1] of the x–z cross-section of
/// `cross_section` (its y bounds are ignored); the last slab is cut at y1.
struct PhiProfile {
    double y0 = 0.0;
    double thickness = 0.0;
    std::vector<double> y_lo;
    std::vector<double> y_hi;
    std::vector<double> phi;
};
PhiProfile packing_fraction_profile(const std::vector<Particle>& particles,
                                    const Box& cross_section, double y0, double y1,
                                    double thickness, unsigned threads = 0);

}  // namespace sgmp::metrics
