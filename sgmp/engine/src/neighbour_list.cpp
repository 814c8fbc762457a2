#include "sgmp/engine/neighbour_list.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace sgmp::engine {

namespace {

/// Cells per axis and their side along one axis of the bounding box [lo, hi]; a periodic
/// axis covers one period [lo, lo + cells·side) and wraps.
struct Axis {
    double lo = 0.0;
    double side = 1.0;
    int cells = 1;
    bool periodic = false;
    [[nodiscard]] int index(double v) const {
        const double c = std::floor((v - lo) / side);
        if (periodic) {
            const int k = static_cast<int>(std::fmod(c, static_cast<double>(cells)));
            return k < 0 ? k + cells : k;
        }
        return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(cells - 1)));
    }
    /// The distinct cells next to cell c and c itself: at most three, wrapped when periodic
    /// (every cell when a period holds fewer than three).
    [[nodiscard]] std::array<int, 3> around(int c, int& count) const {
        if (periodic && cells < 3) {
            count = cells;
            return {0, 1, 2};
        }
        if (periodic) {
            count = 3;
            return {(c + cells - 1) % cells, c, (c + 1) % cells};
        }
        const int lo_cell = std::max(c - 1, 0);
        count = std::min(c + 1, cells - 1) - lo_cell + 1;
        return {lo_cell, lo_cell + 1, lo_cell + 2};
    }
};

/// Cells of side at least `min_side` over [lo, hi]; at most `max_cells` along the axis.
Axis make_axis(double lo, double hi, double min_side, int max_cells) {
    Axis axis;
    axis.lo = lo;
    const double n = std::floor((hi - lo) / min_side);
    axis.cells = static_cast<int>(std::clamp(n, 1.0, static_cast<double>(max_cells)));
    axis.side = std::max((hi - lo) / axis.cells, min_side);
    return axis;
}

Axis axis_over(const std::vector<Ball>& balls, double Ball::*coordinate, double min_side,
               int max_cells) {
    double lo = INFINITY;
    double hi = -INFINITY;
    for (const Ball& b : balls) {
        lo = std::min(lo, b.*coordinate);
        hi = std::max(hi, b.*coordinate);
    }
    return make_axis(lo, hi, min_side, max_cells);
}

/// A periodic axis over the period [lo, hi): as many cells of side ≥ min_side as fit.
Axis periodic_axis(double lo, double hi, double min_side) {
    Axis axis = make_axis(lo, hi, min_side, 4096);
    axis.side = (hi - lo) / axis.cells;
    axis.periodic = true;
    return axis;
}

}  // namespace

void NeighbourList::build(const std::vector<Ball>& s, double skin, const Container& sides) {
    const std::size_t n = s.size();
    offsets_.assign(n + 1, 0);
    neighbours_.clear();
    if (n == 0) {
        return;
    }
    double r_max = 0.0;
    for (const Ball& b : s) {
        r_max = std::max(r_max, b.r);
    }
    const double min_side = 2.0 * r_max + skin;
    const Axis ax = sides.periodic ? periodic_axis(sides.x_min, sides.x_max, min_side)
                                   : axis_over(s, &Ball::x, min_side, 4096);
    const Axis az = sides.periodic ? periodic_axis(sides.z_min, sides.z_max, min_side)
                                   : axis_over(s, &Ball::z, min_side, 4096);
    // At most four cells per sphere, so the cell array never outgrows the spheres' (a tall,
    // thin pile gets taller cells).
    const double layers = std::ceil(4.0 * static_cast<double>(n) / (ax.cells * az.cells));
    const Axis ay = axis_over(s, &Ball::y, min_side, static_cast<int>(std::min(layers, 1e6)));
    const auto cell = [&](int ix, int iy, int iz) {
        return (static_cast<std::uint32_t>(iy) * az.cells + iz) * ax.cells + ix;
    };
    const std::size_t cell_count = static_cast<std::size_t>(ax.cells) * ay.cells * az.cells;
    cell_of_.resize(n);
    cell_start_.assign(cell_count + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        cell_of_[i] = cell(ax.index(s[i].x), ay.index(s[i].y), az.index(s[i].z));
        ++cell_start_[cell_of_[i] + 1];
    }
    for (std::size_t c = 0; c < cell_count; ++c) {
        cell_start_[c + 1] += cell_start_[c];
    }
    by_cell_.resize(n);
    std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
        by_cell_[fill[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
    }
    for (std::size_t i = 0; i < n; ++i) {
        int count_x = 0;
        int count_z = 0;
        const std::array<int, 3> xs = ax.around(ax.index(s[i].x), count_x);
        const std::array<int, 3> zs = az.around(az.index(s[i].z), count_z);
        const int cy = ay.index(s[i].y);
        for (int iy = std::max(cy - 1, 0); iy <= std::min(cy + 1, ay.cells - 1); ++iy) {
            for (int kz = 0; kz < count_z; ++kz) {
                for (int kx = 0; kx < count_x; ++kx) {
                    const std::uint32_t c = cell(xs[kx], iy, zs[kz]);
                    for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
                        const std::uint32_t j = by_cell_[k];
                        if (j <= i) {
                            continue;
                        }
                        double dx = s[j].x - s[i].x;
                        const double dy = s[j].y - s[i].y;
                        double dz = s[j].z - s[i].z;
                        sides.to_nearest_image(dx, dz);
                        const double reach = s[i].r + s[j].r + skin;
                        if (dx * dx + dy * dy + dz * dz < reach * reach) {
                            neighbours_.push_back(j);
                        }
                    }
                }
            }
        }
        offsets_[i + 1] = static_cast<std::uint32_t>(neighbours_.size());
    }
}

}  // namespace sgmp::engine
