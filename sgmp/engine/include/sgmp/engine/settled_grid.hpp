#pragma once
/// @file settled_grid.hpp
/// Uniform grid over the container holding the settled particles, so that a drop only
/// looks at nearby cells and the work per drop does not grow with N.
///
/// Cells are cubes of side h ≥ `min_cell` (the container's width is divided into
/// ⌊width / min_cell⌋ equal columns, so cells tile the walls exactly); layer l covers
/// y ∈ [floor + l·h, floor + (l+1)·h). Layers are added upward as particles settle higher,
/// so the grid only ever spans the settled pack. Points outside the walls are clamped to
/// the edge cells. Only settled particles are stored: particles still waiting to fall are
/// never obstacles.
///
/// Storage: one block of cells per layer, z fastest (the order a box scan walks them). Each cell
/// holds its first `kInline` spheres in place (a cell of one diameter holds about 1.1 spheres of a
/// pack at φ ≈ 0.58), later ones in a spill list of the cell; a cell yields its spheres in
/// insertion order. One scan of a box reads a few contiguous runs of memory instead of one heap
/// block per cell.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "sgmp/pack/geometry.hpp"

namespace sgmp::engine {

/// A settled sphere as the grid stores it (plain numbers, for cache-friendly scans).
struct Sphere {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    double r = 0.0;
};

/// Inclusive range of cell indices along one axis.
struct CellRange {
    int lo = 0;
    int hi = -1;
};

class SettledGrid {
  public:
    /// `min_cell` > 0 is the smallest allowed cell side (typically the largest diameter).
    SettledGrid(const Container& container, double min_cell);

    void insert(const Sphere& sphere);
    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] double cell_side_x() const { return hx_; }
    [[nodiscard]] double cell_side_y() const { return hy_; }
    /// Number of layers holding cells so far (0 when empty).
    [[nodiscard]] int layers() const { return layers_; }
    /// Layer containing height y (may be ≥ layers(); negative heights map to layer 0).
    [[nodiscard]] int layer_of(double y) const;
    /// Bottom height of layer l.
    [[nodiscard]] double layer_bottom(int l) const { return floor_ + l * hy_; }
    /// Column indices whose cells meet [lo, hi] along x (resp. z), clamped to the grid.
    [[nodiscard]] CellRange x_range(double lo, double hi) const;
    [[nodiscard]] CellRange z_range(double lo, double hi) const;

    /// Calls f(const Sphere&) for every sphere stored in layer l within the column ranges.
    template <class F>
    void for_each_in_layer(int l, CellRange xs, CellRange zs, F&& f) const {
        if (l < 0 || l >= layers_) {
            return;
        }
        const Cell* layer = layers_cells_[static_cast<std::size_t>(l)].get();
        for (int ix = xs.lo; ix <= xs.hi; ++ix) {
            const Cell* row = layer + static_cast<std::size_t>(ix) * nz_;
            for (const Cell* cell = row + zs.lo; cell <= row + zs.hi; ++cell) {
                const Cell& c = *cell;
                const std::uint32_t in_place = std::min<std::uint32_t>(c.count, kInline);
                for (std::uint32_t k = 0; k < in_place; ++k) {
                    f(c.spheres[k]);
                }
                if (c.count > kInline) {
                    for (const Sphere& s : spill_[c.spill]) {
                        f(s);
                    }
                }
            }
        }
    }

    /// Calls f(const Sphere&) for every sphere stored in cells meeting the box [lo, hi]; the
    /// caller tests exact distances.
    template <class F>
    void for_each_in_box(const Vec3& lo, const Vec3& hi, F&& f) const {
        const CellRange xs = x_range(lo.x(), hi.x());
        const CellRange zs = z_range(lo.z(), hi.z());
        const int top = std::min(layer_of(hi.y()), layers_ - 1);
        for (int l = layer_of(lo.y()); l <= top; ++l) {
            for_each_in_layer(l, xs, zs, f);
        }
    }

  private:
    double x_min_;
    double z_min_;
    double floor_;
    double hx_;
    double hz_;
    double hy_;
    int nx_;
    int nz_;
    int layers_ = 0;
    std::size_t size_ = 0;
    static constexpr std::uint32_t kInline = 2;
    struct Cell {
        Sphere spheres[kInline];
        std::uint32_t count = 0;
        std::uint32_t spill = 0;  ///< index into spill_ once count > kInline
    };
    /// One block of nx·nz cells per layer (x major, z fastest), allocated as layers are
    /// reached, so growing the grid never copies it.
    std::vector<std::unique_ptr<Cell[]>> layers_cells_;
    /// Spheres past the first kInline of a cell, one list per such cell.
    std::vector<std::vector<Sphere>> spill_;
};

/// Lowest height y ≥ `from` at which a sphere of radius r centred at (x, ·, z) overlaps no
/// sphere of `grid` (touching allowed). Every sphere j with horizontal distance h < r + r_j
/// blocks the open interval y_j ± √((r + r_j)² − h²); the answer is the first point at or
/// above `from` outside all of them. `r_max` bounds the stored radii; `scratch` is reused.
double lowest_free_height(const SettledGrid& grid, double x, double z, double r, double r_max,
                          double from, std::vector<std::pair<double, double>>& scratch);

}  // namespace sgmp::engine
