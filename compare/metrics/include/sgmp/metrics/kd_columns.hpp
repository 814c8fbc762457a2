#pragma once
/// @file kd_columns.hpp
/// The comparison's neighbour search for its pair passes (Z(δ), g(r), the split ratio, Q6;
/// overlaps are counted by the project's one overlap search, sgmp/pack/pack_overlaps.hpp):
/// CGAL's kd-tree (Spatial_searching, Kd_tree with the Sliding_midpoint splitter) over the
/// centres' (x, y), whose leaves are whole columns of centres.
///
/// Each leaf of the tree is one column: its centres are stored contiguously, sorted by z
/// (then index), as structure-of-arrays (x, y, z, index), columns in the tree's order
/// (lower child first). A column's footprint F_c is the tight rectangle of its centres'
/// (x, y). The leaves hold at most ⌈2·n·side²/A⌉ centres (A the area of the centres' (x, y)
/// bounding rectangle widened by side), about half of that on average, so a column covers
/// about side² of the floor.
///
/// Query: for a rectangle R and a radius ρ, the columns c with s_c = dist(R, F_c) ≤ ρ,
/// found by walking the tree from its root and leaving out every subtree whose tight
/// bounds along a node's cutting dimension lie farther than ρ from R. For a centre p over
/// R and a centre q of column c with |p − q| ≤ ρ, the horizontal distance is ≥ s_c, so
/// |z_p − z_q| ≤ √(ρ² − s_c²): the window of q's column around z_p, which the vector kernels
/// (pair_kernels.hpp) slide up the sorted column. The windows hold every centre within ρ
/// (and some more: the kernels test exact distances), so no result depends on the tree's
/// shape — only the order of floating-point sums over columns does, which the tree fixes
/// (it does not depend on the thread count).
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "sgmp/metrics/neighbour_index.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::metrics {

class KdColumns {
  public:
    /// Columns of about side × side (side > 0) over every particle's centre.
    KdColumns(const std::vector<Particle>& particles, double side, unsigned threads);
    /// The same over the particles `members` only (indices into `particles`).
    KdColumns(const std::vector<Particle>& particles, const std::vector<Index>& members,
              double side, unsigned threads);
    ~KdColumns();
    KdColumns(const KdColumns&) = delete;
    KdColumns& operator=(const KdColumns&) = delete;

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
    struct Tree;
    std::unique_ptr<Tree> tree_;
    std::vector<std::size_t> start_{0};              ///< column c: [start_[c], start_[c+1])
    std::vector<std::array<double, 4>> footprints_;  ///< tight (x, y) rectangle per column
};

}  // namespace sgmp::metrics
