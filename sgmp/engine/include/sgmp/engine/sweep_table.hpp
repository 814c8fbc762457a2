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
        for (std::size_t k = 0; k < static_cast<std::size_t>(positions); ++k) {
            sample_x_.push_back(x_[2 * k]);
            sample_z_.push_back(z_[2 * k]);
        }
    }
    [[nodiscard]] int positions() const { return positions_; }
    /// Unit offset of half-step entry h ∈ [0, 2n).
    [[nodiscard]] double x(int h) const { return x_[h]; }
    [[nodiscard]] double z(int h) const { return z_[h]; }
    /// The n samples alone, contiguous (sample k = entry 2k), for vectorised sweeps.
    [[nodiscard]] const double* sample_x() const { return sample_x_.data(); }
    [[nodiscard]] const double* sample_z() const { return sample_z_.data(); }

  private:
    int positions_;
    std::vector<double> x_;
    std::vector<double> z_;
    std::vector<double> sample_x_;
    std::vector<double> sample_z_;
};

}  // namespace sgmp::engine
