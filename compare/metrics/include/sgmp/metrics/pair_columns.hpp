#pragma once
/// @file pair_columns.hpp
/// The comparison's layout of centres for its pair passes (Z(δ), g(r), the split ratio, Q6;
/// overlaps are counted by the project's one overlap search, sgmp/pack/pack_overlaps.hpp):
/// centres filed in the columns of the testbed's one cell grid (sgmp/pack/incremental_grid
/// .hpp) over their (x, y), each column sorted by z for the vector kernels
/// (pair_kernels.hpp); the columns near a column found by the comparison's neighbour
/// search, CGAL's kd-tree through its own queries (NeighbourIndex over the columns' centres).
///
/// The grid has square columns of side h ≥ `side` over the (x, y) bounding box of the
/// centres, widened until there are at most 2·n + 64 of them (so memory is O(n) for any
/// input), and one layer. Each non-empty column is stored contiguously, sorted by z (then
/// index), as structure-of-arrays (x, y, z, index); columns are numbered x-major. A
/// column's footprint F_c is the tight rectangle of its centres' (x, y), of centre m_c and
/// half-diagonal e_c.
///
/// Query: for a rectangle R (centre m, half-diagonal e) and a radius ρ, the columns c with
/// s_c = dist(R, F_c) ≤ ρ. Every such column has |m − m_c| ≤ ρ + e + e_c ≤ ρ + e + max e_c,
/// so a radius query of the kd-tree over the centres m_c holds them all (widened by
/// 10⁻¹² of itself and by 16 ulp of the largest coordinate, the centres' own rounding); each is
/// then tested exactly against its footprint. For a centre p over R and a centre q of column c with
/// |p − q| ≤ ρ, the horizontal distance is ≥ s_c, so |z_p − z_q| ≤ √(ρ² − s_c²): the window of q's
/// column around z_p, which the vector kernels slide up the sorted column. The windows hold every
/// centre within ρ (and some more: the kernels test exact distances), so no count depends on the
/// columns' side; the order of floating-point sums over columns does, which the layout fixes (it
/// does not depend on the thread count).
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "sgmp/metrics/neighbour_index.hpp"
#include "sgmp/pack/incremental_grid.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::metrics {

class PairColumns {
  public:
    /// Columns of side about `side` (> 0) over every particle's centre.
    PairColumns(const std::vector<Particle>& particles, double side, unsigned threads);
    /// The same over the particles `members` only (indices into `particles`).
    PairColumns(const std::vector<Particle>& particles, const std::vector<Index>& members,
                double side, unsigned threads);
    ~PairColumns();
    PairColumns(const PairColumns&) = delete;
    PairColumns& operator=(const PairColumns&) = delete;

    /// Stored arrays, column by column: centre coordinates and index into `particles`.
    std::vector<double> x, y, z;
    std::vector<Index> index;

    /// Number of columns; column c holds positions [column_begin(c), column_begin(c + 1)).
    [[nodiscard]] std::size_t columns() const { return start_.size() - 1; }
    [[nodiscard]] std::size_t column_begin(std::size_t c) const { return start_[c]; }

    /// {x_lo, x_hi, y_lo, y_hi} of the centres at positions [begin, end) (begin < end).
    [[nodiscard]] std::array<double, 4> footprint(std::size_t begin, std::size_t end) const;

    /// A column met by a query: its number and the half-height √(ρ² − s²) of its windows.
    struct Reach {
        std::size_t column;
        double half;
    };

    /// Replaces `out` with the columns numbered ≥ first_column whose footprint comes within
    /// `radius` of the rectangle `footprint` = {x_lo, x_hi, y_lo, y_hi}, by increasing
    /// number, each with its half-height (widened for rounding).
    void columns_within(const std::array<double, 4>& footprint, double radius,
                        std::size_t first_column, std::vector<Reach>& out) const;

    /// f(column, first, last, half) for each column of columns_within, [first, last) its
    /// positions: for a centre p over the rectangle, the positions with
    /// z_p − half ≤ z ≤ z_p + half hold every centre within `radius` of p.
    template <class F>
    void for_each_column(const std::array<double, 4>& footprint, double radius,
                         std::size_t first_column, F&& f) const {
        std::vector<Reach> reached;
        columns_within(footprint, radius, first_column, reached);
        for (const Reach& r : reached) {
            f(r.column, column_begin(r.column), column_begin(r.column + 1), r.half);
        }
    }

  private:
    std::vector<std::size_t> start_{0};              ///< column c: [start_[c], start_[c+1])
    std::vector<std::array<double, 4>> footprints_;  ///< tight (x, y) rectangle per column
    double widest_ = 0.0;                            ///< the largest half-diagonal e_c
    double scale_ = 0.0;                             ///< the largest |coordinate| of a footprint
    std::unique_ptr<NeighbourIndex> centres_;        ///< the footprints' centres (x, y, 0)
};

}  // namespace sgmp::metrics
