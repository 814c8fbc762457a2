#pragma once
/// @file column_grid.hpp
/// A fine cell grid for neighbour searches out to many cell sides (g(r) to 5·d on cells
/// of side ~d/2). Centres are stored cell by cell (cells numbered z fastest, members of a
/// cell by increasing z, then index) as structure-of-arrays, so the cells of one (x, y)
/// column met by a ball are one contiguous range of the arrays, and a column's centres are
/// sorted by z.
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

#include "sgmp/metrics/neighbour_index.hpp"

namespace sgmp::metrics {

class ColumnGrid {
  public:
    /// Cells of side `side` > 0 over the bounding box of the centres (the side grows when
    /// the centres are spread so far apart that more than 2·N + 64 cells would be needed).
    ColumnGrid(const std::vector<Particle>& particles, double side, bool whole_columns = false);
    /// The same over the particles `members` only (indices into `particles`). With
    /// `whole_columns`, each (x, y) column is one cell (for for_each_window, which needs
    /// no cells in z: fewer cells, and the side stays small when the centres are tall).
    ColumnGrid(const std::vector<Particle>& particles, const std::vector<Index>& members,
               double side, bool whole_columns = false);

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

    /// Number of (x, y) columns; column c holds positions [column_begin(c), column_begin(c + 1)).
    [[nodiscard]] std::size_t columns() const {
        return static_cast<std::size_t>(dims_[0] * dims_[1]);
    }
    [[nodiscard]] std::size_t column_begin(std::size_t c) const {
        return start_[c * static_cast<std::size_t>(dims_[2])];
    }

    /// {x_lo, x_hi, y_lo, y_hi} of the centres at positions [begin, end) (begin < end).
    [[nodiscard]] std::array<double, 4> footprint(std::size_t begin, std::size_t end) const {
        std::array<double, 4> f{x[begin], x[begin], y[begin], y[begin]};
        for (std::size_t p = begin; p < end; ++p) {
            f[0] = std::min(f[0], x[p]);
            f[1] = std::max(f[1], x[p]);
            f[2] = std::min(f[2], y[p]);
            f[3] = std::max(f[3], y[p]);
        }
        return f;
    }

    /// Sliding windows for the centres at positions [begin, end) of one column of `source`
    /// (a grid over the same space; its column's centres sorted by z, their x and y within
    /// `footprint` = {x_lo, x_hi, y_lo, y_hi}): for each column of this grid numbered
    /// ≥ first_column whose footprint comes within `radius` of that rectangle (s the gap),
    /// calls f(column, p, from, to) for every p in [begin, end), increasing, with [from, to)
    /// the positions of the column with |z − z_p| ≤ √(radius² − s²). The windows hold every
    /// centre within radius of p; the caller tests exact distances. One window per column
    /// and origin, found by two pointers that only move up the column.
    template <class F>
    void for_each_window(const ColumnGrid& source, std::size_t begin, std::size_t end,
                         const std::array<double, 4>& footprint, double radius,
                         std::size_t first_column, F&& f) const {
        for_each_column(footprint, radius, first_column,
                        [&](std::size_t column, std::size_t first, std::size_t last, double half) {
                            std::size_t lo = first;
                            std::size_t hi = first;
                            for (std::size_t p = begin; p < end; ++p) {
                                const double zp = source.z[p];
                                while (lo < last && z[lo] < zp - half) {
                                    ++lo;
                                }
                                hi = std::max(hi, lo);
                                while (hi < last && z[hi] <= zp + half) {
                                    ++hi;
                                }
                                f(column, p, lo, hi);
                            }
                        });
    }

    /// The columns of for_each_window: f(column, first, last, half) for each column numbered
    /// ≥ first_column whose footprint comes within `radius` of the rectangle `footprint`,
    /// [first, last) its positions and half = √(radius² − s²) (widened for rounding) the
    /// half-height of the windows: for a centre p over the rectangle, the positions with
    /// z_p − half ≤ z ≤ z_p + half.
    template <class F>
    void for_each_column(const std::array<double, 4>& footprint, double radius,
                         std::size_t first_column, F&& f) const {
        const double wide = radius * (1.0 + 1e-12) + side_ * 1e-12;  // covers rounding
        const double wide2 = wide * wide;
        const std::int64_t x_lo = axis_cell(0, footprint[0] - wide);
        const std::int64_t x_hi = axis_cell(0, footprint[1] + wide);
        const std::int64_t y_lo = axis_cell(1, footprint[2] - wide);
        const std::int64_t y_hi = axis_cell(1, footprint[3] + wide);
        for (std::int64_t i = x_lo; i <= x_hi; ++i) {
            const double sx = range_gap(0, i, footprint[0], footprint[1]);
            for (std::int64_t j = y_lo; j <= y_hi; ++j) {
                const auto column = static_cast<std::size_t>(i * dims_[1] + j);
                if (column < first_column) {
                    continue;
                }
                const double sy = range_gap(1, j, footprint[2], footprint[3]);
                const double rest = wide2 - sx * sx - sy * sy;
                if (rest < 0.0) {
                    continue;
                }
                f(column, column_begin(column), column_begin(column + 1), std::sqrt(rest));
            }
        }
    }

  private:
    /// Distance along axis a from the interval [u, v] to cell k's slab (outer cells reach
    /// to infinity, as in slab_gap).
    [[nodiscard]] double range_gap(int a, std::int64_t k, double u, double v) const {
        const double lo = origin_[a] + static_cast<double>(k) * side_;
        const double hi = lo + side_;
        if (v < lo && k > 0) {
            return lo - v;
        }
        if (u > hi && k < dims_[a] - 1) {
            return u - hi;
        }
        return 0.0;
    }

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

}  // namespace sgmp::metrics
