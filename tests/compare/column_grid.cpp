#include "column_grid.hpp"

#include "sgmp/metrics/parallel.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace sgmp::metrics {

namespace {

/// Members per parallel part of the construction (fixed: the grid never depends on the
/// thread count).
constexpr std::size_t kPartSize = 1 << 16;

std::vector<Index> every_index(std::size_t n) {
    if (n >= std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error("too many particles for the column grid");
    }
    std::vector<Index> all(n);
    for (std::size_t i = 0; i < n; ++i) {
        all[i] = static_cast<Index>(i);
    }
    return all;
}

}  // namespace

ColumnGrid::ColumnGrid(const std::vector<Particle>& particles, double side, bool whole_columns)
    : ColumnGrid(particles, every_index(particles.size()), side, whole_columns) {}

ColumnGrid::ColumnGrid(const std::vector<Particle>& particles, const std::vector<Index>& members,
                       double side, bool whole_columns)
    : side_(side) {
    if (!(side > 0.0) || !std::isfinite(side)) {
        throw std::invalid_argument("the cell side of a column grid must be positive");
    }
    const std::size_t n = members.size();
    // The bounding box (minima and maxima: the same in any order), on the worker threads.
    struct Bounds {
        Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
        Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
        bool finite = true;
    };
    const Bounds bounds = chunked_reduce(
        0, n, kPartSize, Bounds{},
        [&](Bounds& part, std::size_t first, std::size_t last) {
            for (std::size_t i = first; i < last; ++i) {
                const Vec3& c = particles[members[i]].center;
                part.finite = part.finite && c.allFinite();
                part.lo = part.lo.cwiseMin(c);
                part.hi = part.hi.cwiseMax(c);
            }
        },
        [](Bounds& total, const Bounds& part) {
            total.finite = total.finite && part.finite;
            total.lo = total.lo.cwiseMin(part.lo);
            total.hi = total.hi.cwiseMax(part.hi);
        });
    if (!bounds.finite) {
        throw std::invalid_argument("a centre of the column grid is not finite");
    }
    const Vec3 lo = n > 0 ? bounds.lo : Vec3::Zero();
    const Vec3 hi = n > 0 ? bounds.hi : Vec3::Zero();
    const double limit = 2.0 * static_cast<double>(n) + 64.0;
    for (;;) {
        double cells = 1.0;
        for (int a = 0; a < (whole_columns ? 2 : 3); ++a) {
            cells *= std::floor((hi[a] - lo[a]) / side_) + 1.0;
        }
        if (cells <= limit) {
            break;
        }
        side_ *= 1.25;
    }
    std::size_t cells = 1;
    for (int a = 0; a < 3; ++a) {
        origin_[a] = lo[a];
        dims_[a] = a == 2 && whole_columns
                       ? 1
                       : static_cast<std::int64_t>(std::floor((hi[a] - lo[a]) / side_)) + 1;
        cells *= static_cast<std::size_t>(dims_[a]);
    }
    // A stable counting sort by cell in parts of kPartSize members on the worker threads:
    // each part counts its members per cell, and writes them, in their order, after those
    // of the parts before it (the order of a serial counting sort).
    const std::size_t parts = (n + kPartSize - 1) / kPartSize;
    const bool by_parts = parts > 1 && cells * parts <= n;  // the part counts stay small
    const std::size_t part_size = by_parts ? kPartSize : std::max<std::size_t>(n, 1);
    const std::size_t part_count = by_parts ? parts : 1;
    std::vector<std::uint32_t> cell_of(n);
    std::vector<std::uint32_t> counts(part_count * cells, 0);
    parallel_for(0, part_count, [&](std::size_t t) {
        std::uint32_t* const count = counts.data() + t * cells;
        const std::size_t last = std::min(n, (t + 1) * part_size);
        for (std::size_t i = t * part_size; i < last; ++i) {
            const Vec3& c = particles[members[i]].center;
            const auto cell = static_cast<std::size_t>(
                (axis_cell(0, c.x()) * dims_[1] + axis_cell(1, c.y())) * dims_[2] +
                axis_cell(2, c.z()));
            cell_of[i] = static_cast<std::uint32_t>(cell);
            ++count[cell];
        }
    });
    start_.assign(cells + 1, 0);
    for (std::size_t c = 0; c < cells; ++c) {  // counts become each part's first position
        std::uint32_t at = start_[c];
        for (std::size_t t = 0; t < part_count; ++t) {
            const std::uint32_t k = counts[t * cells + c];
            counts[t * cells + c] = at;
            at += k;
        }
        start_[c + 1] = at;
    }
    x.resize(n);
    y.resize(n);
    z.resize(n);
    index.resize(n);
    parallel_for(0, part_count, [&](std::size_t t) {
        std::uint32_t* const next = counts.data() + t * cells;
        const std::size_t last = std::min(n, (t + 1) * part_size);
        for (std::size_t i = t * part_size; i < last; ++i) {
            const std::uint32_t k = next[cell_of[i]]++;
            const Particle& p = particles[members[i]];
            x[k] = p.center.x();
            y[k] = p.center.y();
            z[k] = p.center.z();
            index[k] = members[i];
        }
    });
    // Each cell's members by z, then index, so that every column is sorted by z (cells
    // apart on the worker threads: each is sorted alone, so the result is the same).
    constexpr std::size_t kCellsPerItem = 256;
    parallel_for(0, (cells + kCellsPerItem - 1) / kCellsPerItem, [&](std::size_t item) {
        std::vector<std::pair<double, std::uint32_t>> keyed;  // z, position before sorting
        std::vector<double> xs;
        std::vector<double> ys;
        std::vector<Index> is;
        const std::size_t last_cell = std::min(cells, (item + 1) * kCellsPerItem);
        for (std::size_t c = item * kCellsPerItem; c < last_cell; ++c) {
            const std::size_t begin = start_[c];
            const std::size_t end = start_[c + 1];
            if (end - begin < 2 || std::is_sorted(z.begin() + static_cast<std::ptrdiff_t>(begin),
                                                  z.begin() + static_cast<std::ptrdiff_t>(end))) {
                continue;
            }
            keyed.clear();
            for (std::size_t k = begin; k < end; ++k) {
                keyed.emplace_back(z[k], static_cast<std::uint32_t>(k));  // k increases with index
            }
            std::sort(keyed.begin(), keyed.end());
            xs.assign(x.begin() + static_cast<std::ptrdiff_t>(begin),
                      x.begin() + static_cast<std::ptrdiff_t>(end));
            ys.assign(y.begin() + static_cast<std::ptrdiff_t>(begin),
                      y.begin() + static_cast<std::ptrdiff_t>(end));
            is.assign(index.begin() + static_cast<std::ptrdiff_t>(begin),
                      index.begin() + static_cast<std::ptrdiff_t>(end));
            for (std::size_t k = begin; k < end; ++k) {
                const std::size_t from = keyed[k - begin].second - begin;
                x[k] = xs[from];
                y[k] = ys[from];
                z[k] = keyed[k - begin].first;
                index[k] = is[from];
            }
        }
    });
}

}  // namespace sgmp::metrics
