#include "sgmp/pack/cell_grid.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace sgmp {
namespace {

/// Cells of side h over extents `span`: ⌊span_a / h⌋ + 1 per axis, in doubles (a span of
/// 10²⁰ over a reach of 0.2 is beyond any integer type; the grid widens h until it fits).
std::array<double, 3> dims_for(const Vec3& span, double side) {
    std::array<double, 3> dims{};
    for (int a = 0; a < 3; ++a) {
        dims[a] = std::floor(span[a] / side) + 1.0;
    }
    return dims;
}

double cell_count(const std::array<double, 3>& dims) {
    return dims[0] * dims[1] * dims[2];
}

}  // namespace

CellGrid::CellGrid(const std::vector<Vec3>& centers, double reach, const NeighbourBox& box)
    : box_(box), reach_(reach) {
    if (!(reach > 0.0) || !std::isfinite(reach)) {
        throw std::invalid_argument("cell grid: reach must be a positive finite length");
    }
    if (centers.size() >= std::numeric_limits<std::uint32_t>::max()) {
        throw std::invalid_argument("cell grid: too many centres");
    }
    if (box_.periodic && !(box_.period_x() > 0.0 && box_.period_z() > 0.0 &&
                           std::isfinite(box_.period_x()) && std::isfinite(box_.period_z()))) {
        throw std::invalid_argument("cell grid: the periods must be positive finite lengths");
    }
    Vec3 lo = Vec3::Zero();
    Vec3 hi = Vec3::Zero();
    if (!centers.empty()) {
        lo = hi = centers.front();
    }
    for (const Vec3& c : centers) {
        if (!c.allFinite()) {
            throw std::invalid_argument("cell grid: a centre is not finite");
        }
        lo = lo.cwiseMin(c);
        hi = hi.cwiseMax(c);
    }
    if (box_.periodic) {  // x and z: one period
        lo.x() = box_.x_min;
        hi.x() = box_.x_max;
        lo.z() = box_.z_min;
        hi.z() = box_.z_max;
    }
    grid_ = IncrementalGrid<GridPoint>::packed(
        layout_for(lo, hi, reach, centers.size()), centers.size(),
        [&](std::size_t i) {
            const Vec3& c = centers[i];
            return GridPoint{c.x(), c.y(), c.z(), static_cast<std::uint32_t>(i), 0};
        },
        [&](const GridPoint& point) { return box_.wrapped(Vec3(point.x, point.y, point.z)); });
    place_.resize(centers.size());
    const std::vector<GridPoint>& filed = grid_.packed_items();
    for (std::size_t k = 0; k < filed.size(); ++k) {
        place_[filed[k].index] = static_cast<std::uint32_t>(k);
    }
}

CellLayout CellGrid::layout_for(const Vec3& lo, const Vec3& hi, double reach, std::size_t n) const {
    // Widen the cells until the grid holds at most 2n + 64 of them.
    const Vec3 span = hi - lo;
    // (and at most 2³¹ − 1 along any axis: the layout counts cells in int)
    const double max_cells = std::min(2.0 * static_cast<double>(n) + 64.0, 2147483647.0);
    double side = reach;
    if (!span.allFinite()) {
        side = INFINITY;  // centres near ±10³⁰⁸: one cell (every query still exact)
    }
    const auto dims_of = [&](double h) {
        std::array<double, 3> dims = dims_for(span, h);
        for (int a = 0; a < 3; a += 2) {
            if (wraps(a)) {  // whole cells of side ≥ h tile the period
                dims[a] = std::max(1.0, std::floor(span[a] / h));
            }
        }
        return dims;
    };
    while (std::isfinite(side) && cell_count(dims_of(side)) > max_cells) {
        side *= 1.25;
    }
    const std::array<double, 3> dims =
        std::isfinite(side) ? dims_of(side) : std::array<double, 3>{1.0, 1.0, 1.0};
    CellLayout layout;
    layout.x_min = lo.x();
    layout.z_min = lo.z();
    layout.floor = lo.y();
    layout.nx = static_cast<int>(dims[0]);  // at most 2N + 64 by now
    layout.nz = static_cast<int>(dims[2]);
    layout.hx = wraps(0) ? span.x() / dims[0] : side;
    layout.hz = wraps(2) ? span.z() / dims[2] : side;
    layout.hy = side;
    return layout;
}

void CellGrid::wrapped_range(double x, double radius, double origin, double side, int count,
                             std::int64_t& lo, std::int64_t& hi) {
    // x is wrapped into the period; widened far beyond the rounding of a centre's cell.
    const double wide = radius * (1.0 + 1e-12) + side * static_cast<double>(count) * 1e-12;
    const double first = std::floor((x - wide - origin) / side);
    const double last = std::floor((x + wide - origin) / side);
    if (!(last - first + 1.0 < static_cast<double>(count))) {  // also NaN, infinities
        lo = 0;
        hi = count - 1;
        return;
    }
    lo = static_cast<std::int64_t>(first);
    hi = static_cast<std::int64_t>(last);
}

std::vector<Neighbour> CellGrid::nearest(const Vec3& p, std::size_t k) const {
    std::vector<Neighbour> found;
    k = std::min(k, size());
    if (k == 0) {
        return found;
    }
    double radius = cell_side();
    for (;;) {
        found.clear();
        for_each_near(p, radius, [&](std::size_t j, double r2) { found.push_back({j, r2}); });
        if (found.size() >= k || !std::isfinite(radius)) {
            break;
        }
        radius = radius < 1e300 ? 2.0 * radius : INFINITY;
    }
    std::sort(found.begin(), found.end(), nearer);
    found.resize(k);
    return found;
}

std::vector<Vec3> centers_of(const std::vector<Particle>& particles) {
    std::vector<Vec3> centers;
    centers.reserve(particles.size());
    for (const Particle& p : particles) {
        centers.push_back(p.center);
    }
    return centers;
}

}  // namespace sgmp
