#pragma once
/// @file size_classes.hpp
/// Wide blends: packs whose largest radius exceeds twice the smallest. Their neighbour
/// searches keep the small spheres (r ≤ r_max / 2) apart from the large ones and look for
/// each class within its own reach, so that a small sphere never scans cells one large
/// diameter wide (the engine's drop grids, the overlap search, compare's contact search).
#include <vector>

#include "sgmp/pack/particle.hpp"

namespace sgmp {

struct SizeClasses {
    double max_radius = 0.0;        ///< r_max (0 for no particles)
    double min_radius = 0.0;        ///< r_min
    double small_max_radius = 0.0;  ///< the largest radius ≤ r_max / 2 (0 when none)
    /// r_max > 2·r_min: the small and the large spheres are searched apart.
    [[nodiscard]] bool wide() const { return min_radius > 0.0 && max_radius > 2.0 * min_radius; }
    /// A large sphere of a wide blend: r > r_max / 2.
    [[nodiscard]] bool large(double radius) const { return radius > 0.5 * max_radius; }
};

SizeClasses size_classes(const std::vector<Particle>& particles);

}  // namespace sgmp
