#pragma once
/// @file cell_grid.hpp
/// The pack library's neighbour kernel: a uniform cell grid over a fixed set of centres,
/// one of the two implementations of the neighbour-query vocabulary (neighbour_query.hpp).
///
/// Cells are cubes of side h ≥ `reach` over the bounding box of the centres, so every
/// pair with |c_i − c_j| < reach lies in the same or in adjacent cells (the 27-cell
/// stencil). The grid is built by a counting sort (O(N) time, 4·(N + cells) bytes). When
/// the centres are spread far apart, h grows until there are at most 2·N + 64 cells, so
/// memory stays O(N) for any input; a larger h only adds candidates, never loses a pair.
/// Every query tests exact distances, so results do not depend on h.
///
/// In a periodic box (NeighbourBox::periodic) the cells of x and z tile one period (sides
/// period / ⌊period / h⌋, at least h) and wrap; centres are filed by their wrapped
/// position, distances are the box's nearest-image distances, and a query visits each cell
/// at most once, so it meets each centre at most once.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/neighbour_query.hpp"

namespace sgmp {

class CellGrid {
  public:
    /// `reach` > 0 bounds the pair distance of `for_each_pair`. Centres must be finite
    /// (std::invalid_argument otherwise).
    CellGrid(const std::vector<Vec3>& centers, double reach,
             const NeighbourBox& box = NeighbourBox::open());

    [[nodiscard]] std::size_t size() const { return centers_.size(); }
    [[nodiscard]] const NeighbourBox& box() const { return box_; }
    /// The cells' side along y (along x and z too unless periodic).
    [[nodiscard]] double cell_side() const { return side_[1]; }
    [[nodiscard]] const Vec3& center(std::size_t i) const { return centers_[i]; }

    /// Calls f(i, j, distance²) once for every pair i < j with |c_i − c_j| < reach, in
    /// increasing i, then by cell, then by increasing j.
    template <class F>
    void for_each_pair(F&& f) const {
        for_each_pair_from(0, centers_.size(), f);
    }

    /// The same for the pairs whose first member i lies in [first, last): the pairs of
    /// for_each_pair cut by i, for work items of a parallel caller.
    template <class F>
    void for_each_pair_from(std::size_t first, std::size_t last, F&& f) const {
        const double reach2 = reach_ * reach_;
        for (std::size_t i = first; i < last; ++i) {
            const Vec3& c = centers_[i];
            visit_cells(c, reach_, [&](std::uint32_t j) {
                if (j <= i) {
                    return;
                }
                const double r2 = distance2(c, centers_[j]);
                if (r2 < reach2) {
                    f(i, static_cast<std::size_t>(j), r2);
                }
            });
        }
    }

    /// Calls f(j, distance²) for every centre j with |p − c_j| ≤ radius (any radius ≥ 0,
    /// also beyond `reach`; an infinite radius visits every centre).
    template <class F>
    void for_each_near(const Vec3& p, double radius, F&& f) const {
        const double radius2 = radius * radius;
        visit_cells(p, radius, [&](std::uint32_t j) {
            const double r2 = distance2(p, centers_[j]);
            if (r2 <= radius2) {
                f(static_cast<std::size_t>(j), r2);
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
        for (std::size_t i = 0; i < centers_.size(); ++i) {
            const Vec3& c = centers_[i];
            visit_cells(c, radius, [&](std::uint32_t j) {
                if (j > i) {
                    const double r2 = distance2(c, centers_[j]);
                    if (r2 <= radius2) {
                        f(i, static_cast<std::size_t>(j), r2);
                    }
                }
            });
        }
    }

    /// The min(k, size()) centres nearest p, by distance, then index: the centres within
    /// a radius doubled from one cell side until it holds k of them, sorted.
    [[nodiscard]] std::vector<Neighbour> nearest(const Vec3& p, std::size_t k) const;

  private:
    [[nodiscard]] double distance2(const Vec3& a, const Vec3& b) const {
        return box_.periodic ? box_.distance2(a, b) : (b - a).squaredNorm();
    }

    /// Sets the cells' sides for extents `span` (x and z: the periods when wrapping) and
    /// returns the cells per axis.
    std::array<double, 3> size_cells(const Vec3& span, double reach);
    /// Cell index along axis a of coordinate x, clamped to the grid.
    [[nodiscard]] std::int64_t axis_cell(int a, double x) const;
    /// Whether axis a wraps (x and z of a periodic box).
    [[nodiscard]] bool wraps(int a) const { return box_.periodic && a != 1; }
    /// The cells [lo, hi] of axis a meeting [x − radius, x + radius]: clamped to the grid,
    /// or on a wrapping axis unwrapped (taken modulo the cells; every cell once when the
    /// interval covers a period).
    void axis_range(int a, double x, double radius, std::int64_t& lo, std::int64_t& hi) const;
    [[nodiscard]] std::int64_t wrap_cell(int a, std::int64_t c) const {
        if (!wraps(a)) {
            return c;
        }
        const std::int64_t m = c % dims_[a];
        return m < 0 ? m + dims_[a] : m;
    }

    /// Calls g(j) for every centre stored in a cell meeting the cube of half-side
    /// `radius` around p.
    template <class G>
    void visit_cells(const Vec3& p, double radius, G&& g) const {
        std::array<std::int64_t, 3> lo{};
        std::array<std::int64_t, 3> hi{};
        const Vec3 q = box_.wrapped(p);  // p itself when the box is open
        for (int a = 0; a < 3; ++a) {
            axis_range(a, q[a], radius, lo[a], hi[a]);
        }
        for (std::int64_t ux = lo[0]; ux <= hi[0]; ++ux) {
            const std::int64_t ix = wrap_cell(0, ux);
            for (std::int64_t iy = lo[1]; iy <= hi[1]; ++iy) {
                const std::size_t row = static_cast<std::size_t>((ix * dims_[1] + iy) * dims_[2]);
                for (std::int64_t uz = lo[2]; uz <= hi[2]; ++uz) {
                    const std::size_t cell = row + static_cast<std::size_t>(wrap_cell(2, uz));
                    for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
                        g(members_[k]);
                    }
                }
            }
        }
    }

    std::vector<Vec3> centers_;
    NeighbourBox box_;
    double reach_ = 0.0;
    std::array<double, 3> side_{};
    Vec3 origin_ = Vec3::Zero();
    std::array<std::int64_t, 3> dims_{1, 1, 1};
    std::vector<std::uint32_t> start_;    ///< cell c holds members_[start_[c] .. start_[c+1])
    std::vector<std::uint32_t> members_;  ///< centre indices, cell by cell, increasing
};

/// The centres of `particles`, in order (the usual input of CellGrid).
std::vector<Vec3> centers_of(const std::vector<Particle>& particles);

}  // namespace sgmp
