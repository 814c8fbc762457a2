#pragma once
/// @file incremental_grid.hpp
/// The testbed's one cell grid: items (points with their coordinates) inserted one at a time
/// into uniform cells, scanned box by box. The engine drops spheres into it as they settle
/// (SettledGrid); the neighbour-query vocabulary's `CellGrid` (cell_grid.hpp) files a fixed
/// set of centres in it. Every query tests exact distances, so results do not depend on the
/// cells' sides.
///
/// Geometry (`CellLayout`): nx × nz columns of sides hx, hz from (x_min, z_min), and layers
/// of height hy from `floor` upward: layer l covers y ∈ [floor + l·hy, floor + (l+1)·hy).
/// A coordinate outside the columns is filed in the edge cell; layers are added upward as
/// items arrive, so the grid only ever spans what it holds.
///
/// Storage: one block of cells per layer, z fastest (the order a box scan walks them). Each
/// cell holds its first `kInline` items in place, later ones in a spill list of the cell; a
/// cell yields its items in insertion order. One scan of a box reads a few contiguous runs of
/// memory instead of one heap block per cell.
///
/// Memory stays O(items) whatever the layout. Dense layers cost 72 bytes per cell, empty or
/// not: a wide blend's grid of cells of a small diameter (ratio q to the large) would need
/// ~q³ cells per large sphere (ratio 100: 718 MB for 200 spheres; 1000: out of memory). So
/// once the dense layers would exceed kDenseCellsPerItem cells per item (counting the items
/// the caller expects, and kDenseCellFloor cells in all), the grid turns sparse: per layer
/// the occupied cells only, in an ordered map, each cell's items in insertion order, so
/// scans see the same items in the same order as in dense layers, and a scan of many empty
/// cells costs the occupied ones.
///
/// A fixed set of items may instead be filed all at once (`packed`): a counting sort into
/// one array of items, cell by cell in scan order, each cell's items in the order given, and
/// 4 bytes per cell (the layout must then hold at most max(2¹⁸, 64·n) cells); the same
/// scans see the same items in the same order as if they had been inserted one by one.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sgmp/pack/geometry.hpp"

namespace sgmp {

/// Inclusive range of cell indices along one axis.
struct CellRange {
    int lo = 0;
    int hi = -1;
};

/// Where the cells lie: columns over x and z, layers upward from `floor`.
struct CellLayout {
    double x_min = 0.0;
    double z_min = 0.0;
    double floor = 0.0;
    double hx = 1.0;  ///< column side along x (> 0)
    double hz = 1.0;  ///< column side along z (> 0)
    double hy = 1.0;  ///< layer height (> 0)
    int nx = 1;
    int nz = 1;

    /// The container's width divided into ⌊width / min_cell⌋ equal columns along x and z
    /// (at most 4096 each), so that cells tile the walls exactly (and a periodic side's
    /// period), layers as high as the wider column side; `min_cell` > 0.
    static CellLayout over(const Container& container, double min_cell) {
        if (!(min_cell > 0.0)) {
            throw std::invalid_argument("grid cell side must be positive");
        }
        CellLayout layout;
        layout.x_min = container.x_min;
        layout.z_min = container.z_min;
        layout.floor = container.floor;
        layout.nx = columns_for(container.x_max - container.x_min, min_cell);
        layout.nz = columns_for(container.z_max - container.z_min, min_cell);
        layout.hx = (container.x_max - container.x_min) / layout.nx;
        layout.hz = (container.z_max - container.z_min) / layout.nz;
        layout.hy = std::max(layout.hx, layout.hz);
        return layout;
    }
    static int columns_for(double width, double min_cell) {
        const double n = std::floor(width / min_cell);
        return static_cast<int>(std::clamp(n, 1.0, 4096.0));
    }

    /// Cell of `coordinate` along an axis of `count` cells of `side` from `origin`, the edge
    /// cell for coordinates beyond the grid (also for NaN quotients of infinite spans).
    static int index(double coordinate, double origin, double side, int count) {
        const double cell = std::floor((coordinate - origin) / side);
        if (!(cell > 0.0)) {
            return 0;
        }
        return static_cast<int>(std::min(cell, static_cast<double>(count - 1)));
    }
    [[nodiscard]] int column_x(double x) const { return index(x, x_min, hx, nx); }
    [[nodiscard]] int column_z(double z) const { return index(z, z_min, hz, nz); }
    /// Layer containing height y (may be beyond the layers held; negative heights map to 0).
    [[nodiscard]] int layer_of(double y) const {
        const double l = std::floor((y - floor) / hy);
        if (!(l > 0.0)) {
            return 0;
        }
        return static_cast<int>(std::min(l, 1e9));
    }
};

template <class Item>
class IncrementalGrid {
    static_assert(sizeof(Item) == 32, "two items fill one cache line");

  public:
    explicit IncrementalGrid(const CellLayout& layout, std::size_t expected_items = 0)
        : layout_(layout), expected_(expected_items) {}
    IncrementalGrid(const IncrementalGrid&) = delete;
    IncrementalGrid& operator=(const IncrementalGrid&) = delete;
    IncrementalGrid(IncrementalGrid&&) noexcept = default;
    IncrementalGrid& operator=(IncrementalGrid&&) noexcept = default;

    /// A grid holding the items item_of(0), …, item_of(count − 1), each filed in the cell of
    /// filed_at(item) (a Vec3), packed (see the file's comment); insert() then throws
    /// std::logic_error. Memory while filing: the items, 8 bytes per item and 4 per cell.
    template <class ItemOf, class FiledAt>
    static IncrementalGrid packed(const CellLayout& layout, std::size_t count, ItemOf&& item_of,
                                  FiledAt&& filed_at);

    /// Files `item` in the cell of its x, y, z, after the cell's earlier items.
    void insert(const Item& item) { insert(item, item.x, item.y, item.z); }
    /// True for a grid made by `packed`.
    [[nodiscard]] bool is_packed() const { return packed_; }
    /// A packed grid's items, cell by cell in scan order (empty otherwise).
    [[nodiscard]] const std::vector<Item>& packed_items() const { return packed_items_; }
    /// Files `item` in the cell of (x, y, z) (e.g. a periodic point's wrapped position).
    void insert(const Item& item, double x, double y, double z);
    /// Empties the grid and moves it to `layout`, keeping the memory of its layers for reuse
    /// when the layout has as many cells per layer.
    void reset(const CellLayout& layout) {
        if (static_cast<std::size_t>(layout.nx) * static_cast<std::size_t>(layout.nz) !=
            cells_per_layer()) {
            layer_blocks_.clear();
        }
        layout_ = layout;
        layers_ = 0;
        size_ = 0;
        reused_layers_ = 0;
        spill_.clear();
        sparse_layers_.clear();
        sparse_ = false;  // dense again until the layers outgrow their budget
        packed_ = false;
        packed_start_.clear();
        packed_items_.clear();
    }

    [[nodiscard]] const CellLayout& layout() const { return layout_; }
    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] double cell_side_x() const { return layout_.hx; }
    [[nodiscard]] double cell_side_y() const { return layout_.hy; }
    /// True once the grid keeps only its occupied cells (see the file's comment).
    [[nodiscard]] bool sparse() const { return sparse_; }
    /// Number of layers holding cells so far (0 when empty).
    [[nodiscard]] int layers() const { return layers_; }
    [[nodiscard]] int layer_of(double y) const { return layout_.layer_of(y); }
    /// Bottom height of layer l.
    [[nodiscard]] double layer_bottom(int l) const { return layout_.floor + l * layout_.hy; }
    /// Column indices whose cells meet [lo, hi] along x (resp. z), clamped to the grid.
    [[nodiscard]] CellRange x_range(double lo, double hi) const {
        return {layout_.column_x(lo), layout_.column_x(hi)};
    }
    [[nodiscard]] CellRange z_range(double lo, double hi) const {
        return {layout_.column_z(lo), layout_.column_z(hi)};
    }

    /// Calls f(const Item&) for every item stored in layer l within the column ranges, cell
    /// by cell (x, then z), each cell's items in insertion order.
    template <class F>
    void for_each_in_layer(int l, CellRange xs, CellRange zs, F&& f) const {
        if (l < 0 || l >= layers_) {
            return;
        }
        if (sparse_) {
            for_each_in_sparse_layer(l, xs, zs, f);
            return;
        }
        if (packed_) {
            for (int ix = xs.lo; ix <= xs.hi; ++ix) {
                const std::size_t row = packed_row(l, ix);
                for (std::size_t k = packed_start_[row + zs.lo];
                     k < packed_start_[row + static_cast<std::size_t>(zs.hi) + 1]; ++k) {
                    f(packed_items_[k]);
                }
            }
            return;
        }
        const Layer& layer = layer_blocks_[static_cast<std::size_t>(l)];
        const auto nz = static_cast<std::size_t>(layout_.nz);
        for (int ix = xs.lo; ix <= xs.hi; ++ix) {
            const std::size_t row = static_cast<std::size_t>(ix) * nz;
            for (std::size_t cell = row + zs.lo; cell <= row + zs.hi; ++cell) {
                const Count c = layer.counts[cell];
                const Item* in_place = layer.items + cell * kInline;
                for (std::uint32_t k = 0; k < std::min(c.count, kInline); ++k) {
                    f(in_place[k]);
                }
                if (c.count > kInline) {
                    for (const Item& s : spill_[c.spill]) {
                        f(s);
                    }
                }
            }
        }
    }

    /// Calls f(const Item&) for every item stored in cells meeting the box [lo, hi], layer by
    /// layer upward; the caller tests exact distances.
    template <class F>
    void for_each_in_box(const Vec3& lo, const Vec3& hi, F&& f) const {
        const CellRange xs = x_range(lo.x(), hi.x());
        const CellRange zs = z_range(lo.z(), hi.z());
        const int top = std::min(layer_of(hi.y()), layers_ - 1);
        for (int l = layer_of(lo.y()); l <= top; ++l) {
            for_each_in_layer(l, xs, zs, f);
        }
    }

    /// Dense layers are kept while they hold at most kDenseCellsPerItem cells per item, or
    /// kDenseCellFloor cells (19 MB) in all.
    static constexpr std::size_t kDenseCellsPerItem = 64;
    static constexpr std::size_t kDenseCellFloor = std::size_t{1} << 18;

  private:
    /// A sparse layer: its occupied cells by column key ix·nz + iz (the dense order).
    using SparseLayer = std::map<std::uint32_t, std::vector<Item>>;

    /// Moves every stored item from the dense layers into the sparse ones.
    void make_sparse();
    void add_dense_layers(int l);
    [[nodiscard]] std::size_t cells_per_layer() const {
        return static_cast<std::size_t>(layout_.nx) * static_cast<std::size_t>(layout_.nz);
    }
    [[nodiscard]] std::uint32_t column_key(int ix, int iz) const {
        return static_cast<std::uint32_t>(ix) * static_cast<std::uint32_t>(layout_.nz) +
               static_cast<std::uint32_t>(iz);
    }
    /// for_each_in_layer of a sparse layer: an empty layer costs nothing, and a layer is
    /// walked whole (fewer occupied cells than columns scanned) or from each column's first
    /// cell in range, so a large sphere's scan of a fine grid costs the items near it, not
    /// its cells.
    template <class F>
    void for_each_in_sparse_layer(int l, CellRange xs, CellRange zs, F&& f) const {
        if (static_cast<std::size_t>(l) >= sparse_layers_.size()) {
            return;
        }
        const SparseLayer& layer = sparse_layers_[static_cast<std::size_t>(l)];
        if (layer.empty() || xs.hi < xs.lo || zs.hi < zs.lo) {
            return;
        }
        const auto visit = [&](const std::vector<Item>& items) {
            for (const Item& s : items) {
                f(s);
            }
        };
        const auto nz = static_cast<std::uint32_t>(layout_.nz);
        if (layer.size() < static_cast<std::size_t>(xs.hi - xs.lo + 1)) {
            for (const auto& [key, items] : layer) {
                const int ix = static_cast<int>(key / nz);
                const int iz = static_cast<int>(key % nz);
                if (ix >= xs.lo && ix <= xs.hi && iz >= zs.lo && iz <= zs.hi) {
                    visit(items);
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

    /// First cell of row (l, ix) of a packed grid.
    [[nodiscard]] std::size_t packed_row(int l, int ix) const {
        return (static_cast<std::size_t>(l) * static_cast<std::size_t>(layout_.nx) +
                static_cast<std::size_t>(ix)) *
               static_cast<std::size_t>(layout_.nz);
    }

    CellLayout layout_;
    bool packed_ = false;
    std::vector<std::uint32_t> packed_start_;  ///< cell c: packed_items_[start[c], start[c+1])
    std::vector<Item> packed_items_;
    std::size_t expected_ = 0;  ///< items the caller will insert (the dense budget's count)
    int layers_ = 0;
    int reused_layers_ = 0;  ///< layers whose counts have been cleared since the last reset
    std::size_t size_ = 0;
    static constexpr std::uint32_t kInline = 2;
    struct Count {
        std::uint32_t count = 0;  ///< items in the cell
        std::uint32_t spill = 0;  ///< index into spill_ once count > kInline
    };
    /// One layer: nx·nz cells (x major, z fastest). The counts are cleared when the layer is
    /// reached; the item slots (kInline per cell) are never initialised, so their memory is
    /// touched only where items are stored.
    /// (Both in one allocation, counts first: separate small blocks of counts fragmented
    /// the heap and raised the peak memory of a 10^6 pack by 24 MB.)
    struct Layer {
        std::unique_ptr<std::byte[]> memory;
        Count* counts = nullptr;
        Item* items = nullptr;
    };
    /// Blocks allocated as layers are reached (growing never copies); `reset` keeps them.
    std::vector<Layer> layer_blocks_;
    /// Items past the first kInline of a cell, one list per such cell.
    std::vector<std::vector<Item>> spill_;
    /// Sparse: per layer the occupied cells, each with its items in insertion order.
    bool sparse_ = false;
    std::vector<SparseLayer> sparse_layers_;
};

template <class Item>
template <class ItemOf, class FiledAt>
IncrementalGrid<Item> IncrementalGrid<Item>::packed(const CellLayout& layout, std::size_t count,
                                                    ItemOf&& item_of, FiledAt&& filed_at) {
    IncrementalGrid grid(layout, count);
    grid.packed_ = true;
    if (count >= std::size_t{0xffffffffu}) {
        throw std::length_error("cell grid: too many items");
    }
    std::vector<std::size_t> cell_of(count);
    int layers = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3 at = filed_at(item_of(k));
        const int l = layout.layer_of(at.y());
        layers = std::max(layers, l + 1);
        cell_of[k] = static_cast<std::size_t>(l) * grid.cells_per_layer() +
                     static_cast<std::size_t>(layout.column_x(at.x())) *
                         static_cast<std::size_t>(layout.nz) +
                     static_cast<std::size_t>(layout.column_z(at.z()));
    }
    const std::size_t cells = static_cast<std::size_t>(layers) * grid.cells_per_layer();
    if (cells > std::max(kDenseCellFloor, kDenseCellsPerItem * count)) {
        throw std::length_error("cell grid: a packed layout of more cells than its items allow");
    }
    grid.layers_ = layers;
    grid.packed_start_.assign(cells + 1, 0);
    for (const std::size_t c : cell_of) {
        ++grid.packed_start_[c + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) {
        grid.packed_start_[c + 1] += grid.packed_start_[c];
    }
    grid.packed_items_.resize(count);
    for (std::size_t k = 0; k < count; ++k) {  // cell_of[k] becomes k's place
        cell_of[k] = grid.packed_start_[cell_of[k]]++;
    }
    for (std::size_t c = cells; c > 0; --c) {  // the starts, moved one cell on, moved back
        grid.packed_start_[c] = grid.packed_start_[c - 1];
    }
    grid.packed_start_[0] = 0;
    for (std::size_t k = 0; k < count; ++k) {
        grid.packed_items_[cell_of[k]] = item_of(k);
    }
    grid.size_ = count;
    return grid;
}

template <class Item>
void IncrementalGrid<Item>::make_sparse() {
    sparse_layers_.assign(static_cast<std::size_t>(layers_), SparseLayer{});
    for (int l = 0; l < layers_; ++l) {
        for (int ix = 0; ix < layout_.nx; ++ix) {
            for (int iz = 0; iz < layout_.nz; ++iz) {
                std::vector<Item> items;
                for_each_in_layer(l, CellRange{ix, ix}, CellRange{iz, iz},
                                  [&](const Item& s) { items.push_back(s); });
                if (!items.empty()) {
                    sparse_layers_[static_cast<std::size_t>(l)].emplace(column_key(ix, iz),
                                                                        std::move(items));
                }
            }
        }
    }
    sparse_ = true;
    layer_blocks_.clear();
    layer_blocks_.shrink_to_fit();
    spill_.clear();
    spill_.shrink_to_fit();
    reused_layers_ = 0;
}

template <class Item>
void IncrementalGrid<Item>::add_dense_layers(int l) {
    const std::size_t cells = cells_per_layer();
    while (static_cast<int>(layer_blocks_.size()) <= l) {
        static_assert(sizeof(Count) % alignof(Item) == 0);
        Layer layer;
        // The item slots start on a cache line, so that a cell's slots are one line, not two.
        constexpr std::size_t kLine = 64;
        static_assert(kInline * sizeof(Item) == kLine);
        const std::size_t counts_bytes = (cells * sizeof(Count) + kLine - 1) / kLine * kLine;
        const std::size_t bytes = counts_bytes + cells * kLine;
        std::size_t space = kLine + bytes;
        layer.memory = std::make_unique_for_overwrite<std::byte[]>(space);
        void* start = layer.memory.get();
        std::byte* base = static_cast<std::byte*>(std::align(kLine, bytes, start, space));
        layer.counts = reinterpret_cast<Count*>(base);
        layer.items = reinterpret_cast<Item*>(base + counts_bytes);
        layer_blocks_.push_back(std::move(layer));
    }
    // New layers, and layers reached again after a reset, are cleared when first reached.
    for (int k = reused_layers_; k <= l; ++k) {
        std::fill_n(layer_blocks_[static_cast<std::size_t>(k)].counts, cells, Count{});
    }
    reused_layers_ = std::max(reused_layers_, l + 1);
    layers_ = l + 1;
}

template <class Item>
void IncrementalGrid<Item>::insert(const Item& item, double x, double y, double z) {
    if (packed_) {
        throw std::logic_error("cell grid: no insert into a packed grid");
    }
    const int l = layer_of(y);
    const std::size_t cells = cells_per_layer();
    const std::size_t budget = std::max(expected_, size_ + 1);
    if (!sparse_ && l >= static_cast<int>(layer_blocks_.size()) &&
        (static_cast<std::size_t>(l) + 1) * cells >
            std::max(kDenseCellFloor, kDenseCellsPerItem * budget)) {
        make_sparse();
    }
    const int ix = layout_.column_x(x);
    const int iz = layout_.column_z(z);
    if (sparse_) {
        layers_ = std::max(layers_, l + 1);
        if (sparse_layers_.size() < static_cast<std::size_t>(layers_)) {
            sparse_layers_.resize(static_cast<std::size_t>(layers_));
        }
        sparse_layers_[static_cast<std::size_t>(l)][column_key(ix, iz)].push_back(item);
        ++size_;
        return;
    }
    if (l >= layers_) {
        add_dense_layers(l);
    }
    Layer& layer = layer_blocks_[static_cast<std::size_t>(l)];
    const std::size_t cell = static_cast<std::size_t>(ix) * static_cast<std::size_t>(layout_.nz) +
                             static_cast<std::size_t>(iz);
    Count& count = layer.counts[cell];
    if (count.count < kInline) {
        layer.items[cell * kInline + count.count] = item;
    } else {
        if (count.count == kInline) {
            count.spill = static_cast<std::uint32_t>(spill_.size());
            spill_.emplace_back();
        }
        spill_[count.spill].push_back(item);
    }
    ++count.count;
    ++size_;
}

}  // namespace sgmp
