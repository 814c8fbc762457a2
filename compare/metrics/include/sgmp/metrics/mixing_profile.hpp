#pragma once
/// @file mixing_profile.hpp
/// How well a blend is mixed over height: each species' share of the solid volume in each
/// quarter of the bed.
///
/// The bed is y ∈ [floor, top − d_max] (top = max(yᵢ + rᵢ), d_max the largest diameter):
/// the top layer of one largest diameter, loose by construction, is left out. It is cut
/// into four equal slabs q. Each sphere's volume in a slab is exact (the sphere cut by two
/// planes, from the cap volume V(u) = π(r + u)²(2r − u)/3 of the part below u, measured
/// from the centre), so a sphere across a boundary counts in both. For species s,
///
///     share(s, q) = V(s, q) / Σ_s' V(s', q),     overall(s) = Σ_q V(s, q) / Σ_s',q V(s', q),
///
/// and the deviation is max over s, q of |share(s, q) − overall(s)|: 0 for a perfectly mixed
/// bed, up to 1 for one species per quarter. Spheres lie inside the container's walls, so
/// no lateral clipping is needed.
#include <array>
#include <optional>
#include <vector>

#include "sgmp/pack/particle.hpp"

namespace sgmp::metrics {

struct MixingProfile {
    std::vector<int> species;                     ///< the species present, increasing
    double y_low = 0.0;                           ///< the bed's bottom (the floor)
    double y_high = 0.0;                          ///< top − d_max
    std::vector<double> overall;                  ///< per species
    std::array<std::vector<double>, 4> quarters;  ///< bottom first; per species
    double deviation = 0.0;
};

/// Volume of the ball of radius r centred at height c between heights y0 ≤ y1.
double ball_slab_volume(double r, double c, double y0, double y1);

/// The profile of `particles` above `floor`; nullopt when they carry no species (a
/// one-species pack) or the bed is empty (top − d_max ≤ floor).
std::optional<MixingProfile> mixing_profile(const std::vector<Particle>& particles, double floor);

}  // namespace sgmp::metrics
