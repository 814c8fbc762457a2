#pragma once
/// @file bond_order.hpp
/// Steinhardt bond-orientational order of degree 6. For bonds b = c_j − c_i with unit
/// vector u, q_6m(i) = (1/N_b) Σ_j Y_6m(u) and
///     q_6(i) = √( 4π/13 · Σ_{m=−6..6} |q_6m(i)|² ),
/// the local value; the global Q_6 uses the bond average over all origins,
/// Q_6m = Σ_i Σ_j Y_6m / Σ_i N_b(i). Perfect FCC gives 0.57452 (both), simple cubic
/// 0.35355; a random pack has a global Q_6 near 0 and local values near 0.35–0.45.
/// Y_6,−m = (−1)^m conj(Y_6m), so only m = 0..6 are accumulated.

#include <array>
#include <complex>
#include <cstdint>

#include "sgmp/pack/particle.hpp"

namespace sgmp::metrics {

/// Sums of Y_6m, m = 0..6, over a set of bonds.
struct BondSums {
    std::array<std::complex<double>, 7> y{};
    std::int64_t bonds = 0;

    /// Adds the bond of direction `unit` (a unit vector).
    void add(const Vec3& unit);
    void add(const BondSums& other);
    /// √(4π/13 · Σ_m |y_m / bonds|²) over m = −6..6; 0 without bonds.
    [[nodiscard]] double q6() const;
};

}  // namespace sgmp::metrics
