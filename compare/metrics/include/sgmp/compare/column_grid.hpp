#pragma once
/// @file column_grid.hpp
/// A fine cell grid for neighbour searches out to many cell sides (g(r) to 5·d on cells
/// of side ~d/2). Centres are stored cell by cell (cells numbered z fastest, members of a
/// cell by increasing index) as structure-of-arrays, so the cells of one (x, y) column
/// met by a ball are one contiguous range of the arrays.
///
/// A ball B(p, ρ) meets the column (i, j) only if the squared distance s² from p to the
/// column's footprint in x and y is ≤ ρ²; then every centre of B in that column has
/// z ∈ [p_z − √(ρ² − s²), p_z + √(ρ² − s²)], which names a range of its cells. The ranges
/// cover every centre within ρ (and some more: the caller tests exact distances), and
/// their union is about the ball widened by one cell side in x and y only.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sgmp/compare/neighbour_index.hpp"

namespace sgmp::compare {

class ColumnGrid {
  public:
    /// Cells of side `side` > 0 over the bounding box of the centres (the side grows when
    /// the centres are spread so far apart that more than 2·N + 64 cells would be needed).
    ColumnGrid(const std::vector<Particle>& particles, double side);
    /// The same over the particles `members` only (indices into `particles`).
    ColumnGrid(const std::vector<Particle>& particles, const std::vector<Index>& members,
               double side);

    /// `after` of for_each_range: every position.
    static constexpr std::size_t kAll = static_cast<std::size_t>(-1);

    /// Stored arrays, cell by cell: centre coordinates and index into `particles`.
    std::vector<double> x, y, z;
    std::vector<Index> index;

    /// Calls f(begin, end) for ranges of stored positions that together hold every centre
    /// c with |c − p| ≤ radius (ranges are disjoint, in increasing x then y).
    /// With `after` the stored position of p itself, only positions after it: its own
    /// column beyond it and the columns after its own (so that over all stored p, each
    /// pair within radius is met once, from its earlier member).
    template <class F>
    void for_each_range(const Vec3& p, double radius, F&& f, std::size_t after = kAll) const {
        const std::int64_t own =
            after == kAll ? -1 : axis_cell(0, p.x()) * dims_[1] + axis_cell(1, p.y());
        const double wide = radius * (1.0 + 1e-12) + side_ * 1e-12;  // covers cell rounding
        const double wide2 = wide * wide;
        const std::int64_t x_lo = axis_cell(0, p.x() - wide);
        const std::int64_t x_hi = axis_cell(0, p.x() + wide);
        const std::int64_t y_lo = axis_cell(1, p.y() - wide);
        const std::int64_t y_hi = axis_cell(1, p.y() + wide);
        for (std::int64_t i = x_lo; i <= x_hi; ++i) {
            const double sx = slab_gap(0, i, p.x());
            for (std::int64_t j = y_lo; j <= y_hi; ++j) {
                if (i * dims_[1] + j < own) {
                    continue;
                }
                const double sy = slab_gap(1, j, p.y());
                const double rest = wide2 - sx * sx - sy * sy;
                if (rest < 0.0) {
                    continue;
                }
                const double half = std::sqrt(rest);
                const std::size_t row = static_cast<std::size_t>((i * dims_[1] + j) * dims_[2]);
                const std::size_t lo = row + static_cast<std::size_t>(axis_cell(2, p.z() - half));
                const std::size_t hi = row + static_cast<std::size_t>(axis_cell(2, p.z() + half));
                auto begin = static_cast<std::size_t>(start_[lo]);
                if (i * dims_[1] + j == own) {
                    begin = std::max(begin, after + 1);
                }
                f(begin, std::max(begin, static_cast<std::size_t>(start_[hi + 1])));
            }
        }
    }

  private:
    /// Cell of coordinate v along axis a, clamped to the grid.
    [[nodiscard]] std::int64_t axis_cell(int a, double v) const {
        const double c = std::floor((v - origin_[a]) / side_);
        if (!(c >= 0.0)) {
            return 0;
        }
        const auto top = static_cast<double>(dims_[a] - 1);
        return static_cast<std::int64_t>(c < top ? c : top);
    }

    /// Distance along axis a from v to cell k's slab (0 inside; the outer cells reach to
    /// infinity, since clamping puts everything beyond the box in them).
    [[nodiscard]] double slab_gap(int a, std::int64_t k, double v) const {
        const double lo = origin_[a] + static_cast<double>(k) * side_;
        const double hi = lo + side_;
        if (v < lo && k > 0) {
            return lo - v;
        }
        if (v > hi && k < dims_[a] - 1) {
            return v - hi;
        }
        return 0.0;
    }

    double side_ = 1.0;
    std::array<double, 3> origin_{};
    std::array<std::int64_t, 3> dims_{1, 1, 1};
    std::vector<std::uint32_t> start_;  ///< cell c holds positions start_[c] .. start_[c+1)
};

}  // namespace sgmp::compare
