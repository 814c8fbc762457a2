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
///
/// Memory stays O(N) whatever the size ratio. Dense layers cost 72 bytes per cell, empty or
/// not: a wide blend's small grid (cells of a small diameter, ratio q to the large) would
/// need ~q³ cells per large sphere (ratio 100: 718 MB for 200 spheres; 1000: out of
/// memory). So once the dense layers would exceed kDenseCellsPerSphere cells per stored
/// sphere (and kDenseCellFloor cells in all), the grid turns sparse: per layer the occupied
/// cells only, in an ordered map, each cell's spheres in insertion order, so scans see the
/// same spheres in the same order as in the dense layers (the same packs, byte for byte),
/// and a scan of many empty cells costs the occupied ones.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
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
    /// Empties the grid and moves it to `container` (same cell sides as before), keeping the
    /// memory of its layers for reuse.
    void reset(const Container& container);
    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] double cell_side_x() const { return hx_; }
    [[nodiscard]] double cell_side_y() const { return hy_; }
    /// True once the grid keeps only its occupied cells (see the file's comment).
    [[nodiscard]] bool sparse() const { return sparse_; }
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
        if (sparse_) {
            for_each_in_sparse_layer(l, xs, zs, f);
            return;
        }
        const Layer& layer = layer_blocks_[static_cast<std::size_t>(l)];
        for (int ix = xs.lo; ix <= xs.hi; ++ix) {
            const std::size_t row = static_cast<std::size_t>(ix) * nz_;
            for (std::size_t cell = row + zs.lo; cell <= row + zs.hi; ++cell) {
                const Count c = layer.counts[cell];
                const Sphere* in_place = layer.spheres + cell * kInline;
                for (std::uint32_t k = 0; k < std::min(c.count, kInline); ++k) {
                    f(in_place[k]);
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

    /// Dense layers are kept while they hold at most kDenseCellsPerSphere cells per stored
    /// sphere, or kDenseCellFloor cells (19 MB) in all.
    static constexpr std::size_t kDenseCellsPerSphere = 64;
    static constexpr std::size_t kDenseCellFloor = std::size_t{1} << 18;

  private:
    /// A sparse layer: its occupied cells by column key ix·nz + iz (the dense order).
    using SparseLayer = std::map<std::uint32_t, std::vector<Sphere>>;

    /// Moves every stored sphere from the dense layers into the sparse ones.
    void make_sparse();
    [[nodiscard]] std::uint32_t column_key(int ix, int iz) const {
        return static_cast<std::uint32_t>(ix) * static_cast<std::uint32_t>(nz_) +
               static_cast<std::uint32_t>(iz);
    }
    /// for_each_in_layer of a sparse layer: an empty layer costs nothing, and a layer is
    /// walked whole (fewer occupied cells than columns scanned) or from each column's first
    /// cell in range, so a large sphere's scan of a fine grid costs the spheres near it,
    /// not its cells.
    template <class F>
    void for_each_in_sparse_layer(int l, CellRange xs, CellRange zs, F&& f) const {
        if (static_cast<std::size_t>(l) >= sparse_layers_.size()) {
            return;
        }
        const SparseLayer& layer = sparse_layers_[static_cast<std::size_t>(l)];
        if (layer.empty() || xs.hi < xs.lo || zs.hi < zs.lo) {
            return;
        }
        const auto visit = [&](const std::vector<Sphere>& spheres) {
            for (const Sphere& s : spheres) {
                f(s);
            }
        };
        if (layer.size() < static_cast<std::size_t>(xs.hi - xs.lo + 1)) {
            for (const auto& [key, spheres] : layer) {
                const int ix = static_cast<int>(key / static_cast<std::uint32_t>(nz_));
                const int iz = static_cast<int>(key % static_cast<std::uint32_t>(nz_));
                if (ix >= xs.lo && ix <= xs.hi && iz >= zs.lo && iz <= zs.hi) {
                    visit(spheres);
                }
            }
            return;
        }
        for (int ix = xs.lo; ix <= xs.hi; ++ix) {
            const std::uint32_t last = column_key(ix, zs.hi);
            for (auto it = layer.lower_bound(column_key(ix, zs.lo));
                 it != layer.end() && it->first <= last; ++it) {
                visit(it->second);
            }
        }
    }

    double x_min_;
    double z_min_;
    double floor_;
    double hx_;
    double hz_;
    double hy_;
    int nx_;
    int nz_;
    int layers_ = 0;
    int reused_layers_ = 0;  ///< layers whose counts have been cleared since the last reset
    std::size_t size_ = 0;
    static constexpr std::uint32_t kInline = 2;
    struct Count {
        std::uint32_t count = 0;  ///< spheres in the cell
        std::uint32_t spill = 0;  ///< index into spill_ once count > kInline
    };
    /// One layer: nx·nz cells (x major, z fastest). The counts are cleared when the layer is
    /// reached; the sphere slots (kInline per cell) are never initialised, so their memory is
    /// touched only where spheres are stored.
    /// (Both in one allocation, counts first: separate small blocks of counts fragmented
    /// the heap and raised the peak memory of a 10^6 pack by 24 MB.)
    struct Layer {
        std::unique_ptr<std::byte[]> memory;
        Count* counts = nullptr;
        Sphere* spheres = nullptr;
    };
    /// Blocks allocated as layers are reached (growing never copies); `reset` keeps them.
    std::vector<Layer> layer_blocks_;
    /// Spheres past the first kInline of a cell, one list per such cell.
    std::vector<std::vector<Sphere>> spill_;
    /// Sparse: per layer the occupied cells, each with its spheres in insertion order.
    bool sparse_ = false;
    std::vector<SparseLayer> sparse_layers_;
};

/// Lowest height y ≥ `from` at which a sphere of radius r centred at (x, ·, z) overlaps no
/// sphere of `grid` (touching allowed). Every sphere j with horizontal distance h < r + r_j
/// blocks the open interval y_j ± √((r + r_j)² − h²); the answer is the first point at or
/// above `from` outside all of them. `r_max` bounds the stored radii; `scratch` is reused.
double lowest_free_height(const SettledGrid& grid, double x, double z, double r, double r_max,
                          double from, std::vector<std::pair<double, double>>& scratch);

}  // namespace sgmp::engine
