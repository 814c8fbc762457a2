#include "sgmp/metrics/pair_columns.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "sgmp/metrics/parallel.hpp"

namespace sgmp::metrics {
namespace {

/// Columns per parallel part of the sort (fixed: the arrays never depend on the thread
/// count).
constexpr std::size_t kColumnsPerPart = 64;

std::vector<Index> every_index(std::size_t n) {
    if (n >= std::numeric_limits<Index>::max()) {
        throw std::length_error("too many particles for the neighbour search");
    }
    std::vector<Index> all(n);
    for (std::size_t i = 0; i < n; ++i) {
        all[i] = static_cast<Index>(i);
    }
    return all;
}

/// Distance from the interval [u, v] to [a, b] (0 when they meet).
double interval_gap(double u, double v, double a, double b) {
    return std::max({0.0, a - v, u - b});
}

/// The centre (x, y, 0) of a footprint {x_lo, x_hi, y_lo, y_hi}.
Vec3 centre_of(const std::array<double, 4>& f) {
    return {0.5 * f[0] + 0.5 * f[1], 0.5 * f[2] + 0.5 * f[3], 0.0};
}

/// Half the diagonal of a footprint.
double half_diagonal(const std::array<double, 4>& f) {
    return 0.5 * std::hypot(f[1] - f[0], f[3] - f[2]);
}

/// A centre as the grid files it: its (x, y), in the grid's (x, z), and its member position.
struct ColumnItem {
    double x = 0.0;
    double y = 0.0;
    std::uint32_t member = 0;
    std::uint32_t unused = 0;
    double unused_slot = 0.0;  // two items to a cache line
};

/// Square columns of side ≥ `side` over the (x, y) rectangle [lo, hi], at most 2·n + 64 of
/// them (the side widened by 1.25 until they fit), one layer: the grid's x is x, its z is y.
CellLayout column_layout(const double (&lo)[2], const double (&hi)[2], double side, std::size_t n) {
    // (and at most 2³¹ − 1 along either axis: the layout counts cells in int)
    const double max_cells = std::min(2.0 * static_cast<double>(n) + 64.0, 2147483647.0);
    const double span[2] = {hi[0] - lo[0], hi[1] - lo[1]};
    const auto cells = [&](double h, int a) { return std::floor(span[a] / h) + 1.0; };
    if (!std::isfinite(span[0]) || !std::isfinite(span[1])) {
        side = INFINITY;  // centres near ±10³⁰⁸: one column (every query still exact)
    }
    while (std::isfinite(side) && cells(side, 0) * cells(side, 1) > max_cells) {
        side *= 1.25;
    }
    CellLayout layout;
    layout.x_min = lo[0];
    layout.z_min = lo[1];
    layout.hx = side;
    layout.hz = side;
    layout.hy = INFINITY;  // one layer
    layout.nx = std::isfinite(side) ? static_cast<int>(cells(side, 0)) : 1;
    layout.nz = std::isfinite(side) ? static_cast<int>(cells(side, 1)) : 1;
    return layout;
}

}  // namespace

PairColumns::PairColumns(const std::vector<Particle>& particles, double side, unsigned threads)
    : PairColumns(particles, every_index(particles.size()), side, threads) {}

PairColumns::PairColumns(const std::vector<Particle>& particles, const std::vector<Index>& members,
                         double side, unsigned threads) {
    if (!(side > 0.0) || !std::isfinite(side)) {
        throw std::invalid_argument("the column side of the neighbour search must be positive");
    }
    const std::size_t n = members.size();
    if (n >= std::numeric_limits<Index>::max()) {
        throw std::length_error("too many particles for the neighbour search");
    }
    double lo[2] = {std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[2] = {-lo[0], -lo[1]};
    for (const Index m : members) {
        const Vec3& c = particles[m].center;
        if (!c.allFinite()) {
            throw std::invalid_argument("a centre of the neighbour search is not finite");
        }
        for (int a = 0; a < 2; ++a) {
            lo[a] = std::min(lo[a], c[a]);
            hi[a] = std::max(hi[a], c[a]);
        }
    }
    if (n == 0) {
        return;
    }
    const CellLayout layout = column_layout(lo, hi, side, n);
    const auto grid = IncrementalGrid<ColumnItem>::packed(
        layout, n,
        [&](std::size_t k) {
            const Vec3& c = particles[members[k]].center;
            return ColumnItem{c.x(), c.y(), static_cast<std::uint32_t>(k), 0};
        },
        [](const ColumnItem& item) { return Vec3(item.x, 0.0, item.y); });

    // The non-empty columns, x-major; their members in the grid's order, then sorted.
    std::vector<std::uint32_t> filed;  // member positions, column by column
    filed.reserve(n);
    for (int ix = 0; ix < layout.nx; ++ix) {
        for (int iy = 0; iy < layout.nz; ++iy) {
            const std::size_t before = filed.size();
            grid.for_each_in_layer(0, CellRange{ix, ix}, CellRange{iy, iy},
                                   [&](const ColumnItem& item) { filed.push_back(item.member); });
            if (filed.size() > before) {
                start_.push_back(filed.size());
            }
        }
    }
    x.resize(n);
    y.resize(n);
    z.resize(n);
    index.resize(n);
    const std::size_t columns = start_.size() - 1;
    footprints_.resize(columns);
    parallel_for(threads, (columns + kColumnsPerPart - 1) / kColumnsPerPart, [&](std::size_t part) {
        const std::size_t last = std::min(columns, (part + 1) * kColumnsPerPart);
        std::vector<std::pair<double, Index>> column;  // (z, particle index)
        for (std::size_t c = part * kColumnsPerPart; c < last; ++c) {
            column.clear();
            for (std::size_t at = start_[c]; at < start_[c + 1]; ++at) {
                const Index i = members[filed[at]];
                column.emplace_back(particles[i].center.z(), i);
            }
            std::sort(column.begin(), column.end());
            for (std::size_t k = 0; k < column.size(); ++k) {
                const std::size_t at = start_[c] + k;
                const Vec3& p = particles[column[k].second].center;
                x[at] = p.x();
                y[at] = p.y();
                z[at] = column[k].first;
                index[at] = column[k].second;
            }
            footprints_[c] = footprint(start_[c], start_[c + 1]);
        }
    });
    std::vector<Vec3> centres(columns);
    for (std::size_t c = 0; c < columns; ++c) {
        centres[c] = centre_of(footprints_[c]);
        widest_ = std::max(widest_, half_diagonal(footprints_[c]));
        for (const double v : footprints_[c]) {
            scale_ = std::max(scale_, std::abs(v));
        }
    }
    centres_ = std::make_unique<NeighbourIndex>(centres);
}

PairColumns::~PairColumns() = default;

std::array<double, 4> PairColumns::footprint(std::size_t begin, std::size_t end) const {
    std::array<double, 4> f{x[begin], x[begin], y[begin], y[begin]};
    for (std::size_t p = begin; p < end; ++p) {
        f[0] = std::min(f[0], x[p]);
        f[1] = std::max(f[1], x[p]);
        f[2] = std::min(f[2], y[p]);
        f[3] = std::max(f[3], y[p]);
    }
    return f;
}

void PairColumns::columns_within(const std::array<double, 4>& footprint, double radius,
                                 std::size_t first_column, std::vector<Reach>& out) const {
    out.clear();
    if (!centres_) {
        return;
    }
    // Widened far beyond rounding: the kernels' exact distance tests decide.
    const double wide = radius * (1.0 + 1e-12) + 1e-300;
    const double wide2 = wide * wide;
    // Widened relatively, and absolutely for the rounding of the centres themselves (each
    // off by up to half an ulp of its coordinates: far from the origin more than 10⁻¹²·ρ).
    const Vec3 centre = centre_of(footprint);
    const double scale = std::max({scale_, std::abs(centre.x()), std::abs(centre.y())});
    const double reach = (wide + half_diagonal(footprint) + widest_) * (1.0 + 1e-12) +
                         16.0 * std::numeric_limits<double>::epsilon() * scale;
    std::vector<Index> near;
    if (std::isfinite(reach) && std::isfinite(centre.norm())) {
        centres_->within(centre, reach, near);
        std::sort(near.begin(), near.end());
    } else {  // spans near ±10³⁰⁸ (or an infinite radius): every column, tested exactly
        near.resize(footprints_.size());
        for (std::size_t c = 0; c < near.size(); ++c) {
            near[c] = static_cast<Index>(c);
        }
    }
    for (const Index c : near) {
        if (c < first_column) {
            continue;
        }
        const std::array<double, 4>& f = footprints_[c];
        const double sx = interval_gap(footprint[0], footprint[1], f[0], f[1]);
        const double sy = interval_gap(footprint[2], footprint[3], f[2], f[3]);
        const double rest = wide2 - sx * sx - sy * sy;
        if (rest >= 0.0) {
            out.push_back({c, std::sqrt(rest)});
        }
    }
}

}  // namespace sgmp::metrics
