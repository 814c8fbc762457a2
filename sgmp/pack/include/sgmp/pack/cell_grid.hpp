#pragma once
/// @file cell_grid.hpp
/// A fixed set of centres filed in the testbed's one cell grid (IncrementalGrid,
/// incremental_grid.hpp), speaking the neighbour-query vocabulary (neighbour_query.hpp):
/// one of its two implementations.
///
/// Cells are cubes of side h ≥ `reach` from the corner of the centres' bounding box, so
/// every pair with |c_i − c_j| < reach lies in the same or in adjacent cells (the 27-cell
/// stencil). When the centres are spread far apart, h grows until there are at most
/// 2·N + 64 cells, so memory stays O(N) for any input; a larger h only adds candidates,
/// never loses a pair. Every query tests exact distances, so results do not depend on h.
///
/// In a periodic box (NeighbourBox::periodic) the cells of x and z tile one period (sides
/// period / ⌊period / h⌋, at least h) and wrap; centres are filed by their wrapped
/// position, distances are the box's nearest-image distances, and a query visits each cell
/// at most once, so it meets each centre at most once.
///
/// Order: a query walks the cells x-major (x, then y, then z; on a wrapping axis from the
/// query's lowest unwrapped cell upward), each cell's centres by increasing index.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/incremental_grid.hpp"
#include "sgmp/pack/neighbour_query.hpp"

namespace sgmp {

class CellGrid {
  public:
    /// `reach` > 0 bounds the pair distance of `for_each_pair`. Centres must be finite
    /// (std::invalid_argument otherwise).
    CellGrid(const std::vector<Vec3>& centers, double reach,
             const NeighbourBox& box = NeighbourBox::open());

    [[nodiscard]] std::size_t size() const { return place_.size(); }
    [[nodiscard]] const NeighbourBox& box() const { return box_; }
    /// The cells' side along y (along x and z too unless periodic).
    [[nodiscard]] double cell_side() const { return grid_.layout().hy; }
    [[nodiscard]] Vec3 center(std::size_t i) const {
        const GridPoint& point = grid_.packed_items()[place_[i]];
        return {point.x, point.y, point.z};
    }

    /// Calls f(i, j, distance²) once for every pair i < j with |c_i − c_j| < reach, in
    /// increasing i, then by cell, then by increasing j.
    template <class F>
    void for_each_pair(F&& f) const {
        for_each_pair_from(0, size(), f);
    }

    /// The same for the pairs whose first member i lies in [first, last): the pairs of
    /// for_each_pair cut by i, for work items of a parallel caller.
    template <class F>
    void for_each_pair_from(std::size_t first, std::size_t last, F&& f) const {
        const double reach2 = reach_ * reach_;
        for (std::size_t i = first; i < last; ++i) {
            const Vec3 c = center(i);
            visit_cells(c, reach_, [&](const GridPoint& point) {
                if (point.index <= i) {
                    return;
                }
                const double r2 = distance2(c, point);
                if (r2 < reach2) {
                    f(i, static_cast<std::size_t>(point.index), r2);
                }
            });
        }
    }

    /// Calls f(j, distance²) for every centre j with |p − c_j| ≤ radius (any radius ≥ 0,
    /// also beyond `reach`; an infinite radius visits every centre).
    template <class F>
    void for_each_near(const Vec3& p, double radius, F&& f) const {
        const double radius2 = radius * radius;
        visit_cells(p, radius, [&](const GridPoint& point) {
            const double r2 = distance2(p, point);
            if (r2 <= radius2) {
                f(static_cast<std::size_t>(point.index), r2);
            }
        });
    }

    /// The vocabulary's names (NeighbourQuery): for_each_near, and every pair i < j within
    /// `radius` (inclusive; any radius ≥ 0) in increasing i, then the cells' order.
    template <class F>
    void for_each_within(const Vec3& p, double radius, F&& f) const {
        for_each_near(p, radius, f);
    }
    template <class F>
    void for_each_pair_within(double radius, F&& f) const {
        const double radius2 = radius * radius;
        for (std::size_t i = 0; i < size(); ++i) {
            const Vec3 c = center(i);
            visit_cells(c, radius, [&](const GridPoint& point) {
                if (point.index > i) {
                    const double r2 = distance2(c, point);
                    if (r2 <= radius2) {
                        f(i, static_cast<std::size_t>(point.index), r2);
                    }
                }
            });
        }
    }

    /// The min(k, size()) centres nearest p, by distance, then index: the centres within
    /// a radius doubled from one cell side until it holds k of them, sorted.
    [[nodiscard]] std::vector<Neighbour> nearest(const Vec3& p, std::size_t k) const;

  private:
    /// A centre as the grid files it: its coordinates and index.
    struct GridPoint {
        double x = 0.0;
        double y = 0.0;
        double z = 0.0;
        std::uint32_t index = 0;
        std::uint32_t unused = 0;
    };

    [[nodiscard]] double distance2(const Vec3& a, const GridPoint& point) const {
        const Vec3 b(point.x, point.y, point.z);
        return box_.periodic ? box_.distance2(a, b) : (b - a).squaredNorm();
    }

    /// The layout of cells of side ≥ reach over the centres' bounding box [lo, hi] (x and
    /// z: one period when wrapping), widened to at most 2·n + 64 cells.
    [[nodiscard]] CellLayout layout_for(const Vec3& lo, const Vec3& hi, double reach,
                                        std::size_t n) const;
    /// Whether axis a wraps (x and z of a periodic box).
    [[nodiscard]] bool wraps(int a) const { return box_.periodic && a != 1; }
    /// The unwrapped cells [lo, hi] of a wrapping axis (cells `count` of `side` from
    /// `origin`) meeting [x − radius, x + radius]: every cell once when the interval
    /// covers a period.
    static void wrapped_range(double x, double radius, double origin, double side, int count,
                              std::int64_t& lo, std::int64_t& hi);
    static int wrap(std::int64_t c, int count) {
        const std::int64_t m = c % count;
        return static_cast<int>(m < 0 ? m + count : m);
    }

    /// Calls g(point) for every centre stored in a cell meeting the cube of half-side
    /// `radius` around p, in the order stated at the top of this file.
    template <class G>
    void visit_cells(const Vec3& p, double radius, G&& g) const {
        const CellLayout& at = grid_.layout();
        const Vec3 q = box_.wrapped(p);  // p itself when the box is open
        const CellRange ys{std::min(at.layer_of(q.y() - radius), grid_.layers() - 1),
                           std::min(at.layer_of(q.y() + radius), grid_.layers() - 1)};
        std::int64_t x_lo = at.column_x(q.x() - radius);
        std::int64_t x_hi = at.column_x(q.x() + radius);
        std::array<CellRange, 2> zs{
            CellRange{at.column_z(q.z() - radius), at.column_z(q.z() + radius)}, CellRange{}};
        if (box_.periodic) {
            wrapped_range(q.x(), radius, at.x_min, at.hx, at.nx, x_lo, x_hi);
            std::int64_t z_lo = 0;
            std::int64_t z_hi = 0;
            wrapped_range(q.z(), radius, at.z_min, at.hz, at.nz, z_lo, z_hi);
            const int first = wrap(z_lo, at.nz);
            const int last = wrap(z_hi, at.nz);
            zs = z_hi < z_lo  // a negative radius: no cell
                     ? std::array<CellRange, 2>{}
                     : first <= last ? std::array<CellRange, 2>{CellRange{first, last}, CellRange{}}
                                     : std::array<CellRange, 2>{CellRange{first, at.nz - 1},
                                                                CellRange{0, last}};
        }
        for (std::int64_t ux = x_lo; ux <= x_hi; ++ux) {
            const int ix = box_.periodic ? wrap(ux, at.nx) : static_cast<int>(ux);
            for (int iy = ys.lo; iy <= ys.hi; ++iy) {
                for (const CellRange& z : zs) {
                    if (z.lo <= z.hi) {
                        grid_.for_each_in_layer(iy, CellRange{ix, ix}, z, g);
                    }
                }
            }
        }
    }

    NeighbourBox box_;
    double reach_ = 0.0;
    IncrementalGrid<GridPoint> grid_{CellLayout{}};
    std::vector<std::uint32_t> place_;  ///< centre i is grid_.packed_items()[place_[i]]
};

/// The centres of `particles`, in order (the usual input of CellGrid).
std::vector<Vec3> centers_of(const std::vector<Particle>& particles);

}  // namespace sgmp
