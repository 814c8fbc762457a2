#pragma once
/// @file random_close_packing.hpp
/// The random-close-packing fraction of polydisperse frictionless spheres predicted from
/// the size distribution by the empirical formula of Desmond & Weeks (Phys. Rev. E 90,
/// 022204, 2014):
///
///     φ_RCP = φ*_RCP + c₁·δ + c₂·S·δ²,   φ*_RCP = 0.634, c₁ = 0.0658, c₂ = 0.0857,
///
/// with, over the spheres (by number), δ = σ_r / ⟨r⟩ the polydispersity and
/// S = ⟨(r − ⟨r⟩)³⟩ / σ_r³ the skewness (σ_r the population standard deviation). Equal
/// spheres give δ = 0 and φ*_RCP; S is 0 when δ = 0.
///
/// The formula is a fit to packings of δ up to 0.4 and skewness between about −2 and 4;
/// beyond, it extrapolates to impossible values (2.7 for a 1 : 0.075 : 0.05 propellant
/// blend), so it is given only inside δ ≤ kDesmondWeeksMaxPolydispersity and
/// kDesmondWeeksMinSkewness ≤ S ≤ kDesmondWeeksMaxSkewness.
#include <optional>
#include <vector>

#include "sgmp/pack/particle.hpp"

namespace sgmp::metrics {

struct SizeMoments {
    double polydispersity = 0.0;  ///< δ
    double skewness = 0.0;        ///< S (0 for one size)
};

/// δ and S of the radii of `particles` (empty: both 0).
SizeMoments size_moments(const std::vector<Particle>& particles);

inline constexpr double kDesmondWeeksPhiStar = 0.634;
inline constexpr double kDesmondWeeksC1 = 0.0658;
inline constexpr double kDesmondWeeksC2 = 0.0857;

inline constexpr double kDesmondWeeksMaxPolydispersity = 0.4;
inline constexpr double kDesmondWeeksMinSkewness = -2.0;
inline constexpr double kDesmondWeeksMaxSkewness = 4.0;

/// φ_RCP of the formula above; nullopt outside its range.
std::optional<double> desmond_weeks_phi_rcp(const SizeMoments& moments);

}  // namespace sgmp::metrics
