#include "sgmp/engine/settled_grid.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace sgmp::engine {

namespace {

int columns_for(double width, double min_cell) {
    const double n = std::floor(width / min_cell);
    return static_cast<int>(std::clamp(n, 1.0, 4096.0));
}

int clamp_index(double coordinate, double origin, double side, int count) {
    const double cell = std::floor((coordinate - origin) / side);
    return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(count - 1)));
}

}  // namespace

SettledGrid::SettledGrid(const Container& container, double min_cell)
    : x_min_(container.x_min), z_min_(container.z_min), floor_(container.floor) {
    if (!(min_cell > 0.0)) {
        throw std::invalid_argument("grid cell side must be positive");
    }
    nx_ = columns_for(container.x_max - container.x_min, min_cell);
    nz_ = columns_for(container.z_max - container.z_min, min_cell);
    hx_ = (container.x_max - container.x_min) / nx_;
    hz_ = (container.z_max - container.z_min) / nz_;
    hy_ = std::max(hx_, hz_);
}

int SettledGrid::layer_of(double y) const {
    const double l = std::floor((y - floor_) / hy_);
    return static_cast<int>(std::clamp(l, 0.0, 1e9));
}

CellRange SettledGrid::x_range(double lo, double hi) const {
    return {clamp_index(lo, x_min_, hx_, nx_), clamp_index(hi, x_min_, hx_, nx_)};
}

CellRange SettledGrid::z_range(double lo, double hi) const {
    return {clamp_index(lo, z_min_, hz_, nz_), clamp_index(hi, z_min_, hz_, nz_)};
}

void SettledGrid::make_sparse() {
    sparse_layers_.assign(static_cast<std::size_t>(layers_), SparseLayer{});
    for (int l = 0; l < layers_; ++l) {
        for (int ix = 0; ix < nx_; ++ix) {
            for (int iz = 0; iz < nz_; ++iz) {
                std::vector<Sphere> spheres;
                for_each_in_layer(l, CellRange{ix, ix}, CellRange{iz, iz},
                                  [&](const Sphere& s) { spheres.push_back(s); });
                if (!spheres.empty()) {
                    sparse_layers_[static_cast<std::size_t>(l)].emplace(column_key(ix, iz),
                                                                        std::move(spheres));
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

void SettledGrid::insert(const Sphere& sphere) {
    const int l = layer_of(sphere.y);
    const std::size_t cells = static_cast<std::size_t>(nx_) * nz_;
    if (!sparse_ && l >= static_cast<int>(layer_blocks_.size()) &&
        (static_cast<std::size_t>(l) + 1) * cells >
            std::max(kDenseCellFloor, kDenseCellsPerSphere * (size_ + 1))) {
        make_sparse();
    }
    if (sparse_) {
        layers_ = std::max(layers_, l + 1);
        if (sparse_layers_.size() < static_cast<std::size_t>(layers_)) {
            sparse_layers_.resize(static_cast<std::size_t>(layers_));
        }
        const int ix = clamp_index(sphere.x, x_min_, hx_, nx_);
        const int iz = clamp_index(sphere.z, z_min_, hz_, nz_);
        sparse_layers_[static_cast<std::size_t>(l)][column_key(ix, iz)].push_back(sphere);
        ++size_;
        return;
    }
    if (l >= layers_) {
        while (static_cast<int>(layer_blocks_.size()) <= l) {
            static_assert(sizeof(Count) % alignof(Sphere) == 0);
            Layer layer;
            // The sphere slots start on a cache line, so that a cell's slots are one line,
            // not two.
            constexpr std::size_t kLine = 64;
            static_assert(kInline * sizeof(Sphere) == kLine);
            const std::size_t counts_bytes = (cells * sizeof(Count) + kLine - 1) / kLine * kLine;
            const std::size_t bytes = counts_bytes + cells * kLine;
            std::size_t space = kLine + bytes;
            layer.memory = std::make_unique_for_overwrite<std::byte[]>(space);
            void* start = layer.memory.get();
            std::byte* base = static_cast<std::byte*>(std::align(kLine, bytes, start, space));
            layer.counts = reinterpret_cast<Count*>(base);
            layer.spheres = reinterpret_cast<Sphere*>(base + counts_bytes);
            layer_blocks_.push_back(std::move(layer));
        }
        // New layers, and layers reached again after a reset, are cleared when first reached.
        for (int k = reused_layers_; k <= l; ++k) {
            std::fill_n(layer_blocks_[static_cast<std::size_t>(k)].counts, cells, Count{});
        }
        reused_layers_ = std::max(reused_layers_, l + 1);
        layers_ = l + 1;
    }
    const int ix = clamp_index(sphere.x, x_min_, hx_, nx_);
    const int iz = clamp_index(sphere.z, z_min_, hz_, nz_);
    Layer& layer = layer_blocks_[static_cast<std::size_t>(l)];
    const std::size_t cell = static_cast<std::size_t>(ix) * nz_ + iz;
    Count& count = layer.counts[cell];
    if (count.count < kInline) {
        layer.spheres[cell * kInline + count.count] = sphere;
    } else {
        if (count.count == kInline) {
            count.spill = static_cast<std::uint32_t>(spill_.size());
            spill_.emplace_back();
        }
        spill_[count.spill].push_back(sphere);
    }
    ++count.count;
    ++size_;
}

void SettledGrid::reset(const Container& container) {
    x_min_ = container.x_min;
    z_min_ = container.z_min;
    floor_ = container.floor;
    layers_ = 0;
    size_ = 0;
    reused_layers_ = 0;
    spill_.clear();
    sparse_layers_.clear();
    sparse_ = false;  // dense again until the layers outgrow their budget
}

double lowest_free_height(const SettledGrid& grid, double x, double z, double r, double r_max,
                          double from, std::vector<std::pair<double, double>>& blocked) {
    blocked.clear();
    const double reach = r + r_max;
    const CellRange xs = grid.x_range(x - reach, x + reach);
    const CellRange zs = grid.z_range(z - reach, z + reach);
    for (int l = grid.layer_of(from - reach); l < grid.layers(); ++l) {
        grid.for_each_in_layer(l, xs, zs, [&](const Sphere& s) {
            const double dx = x - s.x;
            const double dz = z - s.z;
            const double contact = r + s.r;
            const double h2 = dx * dx + dz * dz;
            if (h2 < contact * contact) {
                const double half = std::sqrt(contact * contact - h2);
                blocked.emplace_back(s.y - half, s.y + half);
            }
        });
    }
    std::sort(blocked.begin(), blocked.end());
    double y = from;
    for (const auto& [low, high] : blocked) {
        if (low >= y) {
            break;  // every later interval starts at or above y too
        }
        y = std::max(y, high);
    }
    return y;
}

}  // namespace sgmp::engine
