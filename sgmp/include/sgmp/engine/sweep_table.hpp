#pragma once
/// @file sweep_table.hpp
/// The spin offset table of thesis §4.1, computed once per run: for a sweep of n positions
/// the unit offsets (x, z) = (sin θ, cos θ), θ = 2πk/n (equations 4.1, 4.2 without the
/// radius d/F, which each drop multiplies in). The table holds 2n entries at half steps,
/// θ_h = πh/n, so that sample k is entry 2k and the bisector of any arc of samples
/// (start s, length L) is entry 2s + L − 1 — no sine or cosine is evaluated while packing.
#include <cmath>
#include <numbers>
#include <vector>

namespace sgmp::engine {

class SweepTable {
  public:
    explicit SweepTable(int positions) : positions_(positions) {
        x_.resize(2 * static_cast<std::size_t>(positions));
        z_.resize(x_.size());
        for (std::size_t h = 0; h < x_.size(); ++h) {
            const double theta = std::numbers::pi * static_cast<double>(h) / positions;
            x_[h] = std::sin(theta);
            z_[h] = std::cos(theta);
        }
    }
    [[nodiscard]] int positions() const { return positions_; }
    /// Unit offset of half-step entry h ∈ [0, 2n).
    [[nodiscard]] double x(int h) const { return x_[h]; }
    [[nodiscard]] double z(int h) const { return z_[h]; }

  private:
    int positions_;
    std::vector<double> x_;
    std::vector<double> z_;
};

}  // namespace sgmp::engine
