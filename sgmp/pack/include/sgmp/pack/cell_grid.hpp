#pragma once
/// @file cell_grid.hpp
/// The pack library's neighbour kernel: a uniform cell grid over a fixed set of centres.
///
/// Cells are cubes of side h ≥ `reach` over the bounding box of the centres, so every
/// pair with |c_i − c_j| < reach lies in the same or in adjacent cells (the 27-cell
/// stencil). The grid is built by a counting sort (O(N) time, 4·(N + cells) bytes). When
/// the centres are spread far apart, h grows until there are at most 2·N + 64 cells, so
/// memory stays O(N) for any input; a larger h only adds candidates, never loses a pair.
/// Every query tests exact distances, so results do not depend on h.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sgmp/pack/geometry.hpp"

namespace sgmp {

class CellGrid {
  public:
    /// `reach` > 0 bounds the pair distance of `for_each_pair`. Centres must be finite
    /// (std::invalid_argument otherwise).
    CellGrid(const std::vector<Vec3>& centers, double reach);

    [[nodiscard]] std::size_t size() const { return centers_.size(); }
    [[nodiscard]] double cell_side() const { return side_; }
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
                const double r2 = (centers_[j] - c).squaredNorm();
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
            const double r2 = (centers_[j] - p).squaredNorm();
            if (r2 <= radius2) {
                f(static_cast<std::size_t>(j), r2);
            }
        });
    }

  private:
    /// Cell index along axis a of coordinate x, clamped to the grid.
    [[nodiscard]] std::int64_t axis_cell(int a, double x) const;

    /// Calls g(j) for every centre stored in a cell meeting the cube of half-side
    /// `radius` around p.
    template <class G>
    void visit_cells(const Vec3& p, double radius, G&& g) const {
        std::array<std::int64_t, 3> lo{};
        std::array<std::int64_t, 3> hi{};
        for (int a = 0; a < 3; ++a) {
            lo[a] = axis_cell(a, p[a] - radius);
            hi[a] = axis_cell(a, p[a] + radius);
        }
        for (std::int64_t ix = lo[0]; ix <= hi[0]; ++ix) {
            for (std::int64_t iy = lo[1]; iy <= hi[1]; ++iy) {
                const std::size_t row = static_cast<std::size_t>((ix * dims_[1] + iy) * dims_[2]);
                for (std::int64_t iz = lo[2]; iz <= hi[2]; ++iz) {
                    const std::size_t cell = row + static_cast<std::size_t>(iz);
                    for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
                        g(members_[k]);
                    }
                }
            }
        }
    }

    std::vector<Vec3> centers_;
    double reach_ = 0.0;
    double side_ = 0.0;
    Vec3 origin_ = Vec3::Zero();
    std::array<std::int64_t, 3> dims_{1, 1, 1};
    std::vector<std::uint32_t> start_;    ///< cell c holds members_[start_[c] .. start_[c+1])
    std::vector<std::uint32_t> members_;  ///< centre indices, cell by cell, increasing
};

/// The centres of `particles`, in order (the usual input of CellGrid).
std::vector<Vec3> centers_of(const std::vector<Particle>& particles);

}  // namespace sgmp
