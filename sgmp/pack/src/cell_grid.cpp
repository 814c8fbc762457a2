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
    : centers_(centers), box_(box), reach_(reach) {
    if (!(reach > 0.0) || !std::isfinite(reach)) {
        throw std::invalid_argument("cell grid: reach must be a positive finite length");
    }
    if (centers_.size() >= std::numeric_limits<std::uint32_t>::max()) {
        throw std::invalid_argument("cell grid: too many centres");
    }
    if (box_.periodic && !(box_.period_x() > 0.0 && box_.period_z() > 0.0 &&
                           std::isfinite(box_.period_x()) && std::isfinite(box_.period_z()))) {
        throw std::invalid_argument("cell grid: the periods must be positive finite lengths");
    }
    Vec3 lo = Vec3::Zero();
    Vec3 hi = Vec3::Zero();
    if (!centers_.empty()) {
        lo = hi = centers_.front();
    }
    for (const Vec3& c : centers_) {
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
    origin_ = lo;
    const std::array<double, 3> dims = size_cells(hi - lo, reach);
    for (int a = 0; a < 3; ++a) {
        dims_[a] = static_cast<std::int64_t>(dims[a]);  // at most 2N + 64 by now
    }
    const auto cells = static_cast<std::size_t>(cell_count(dims));

    // Counting sort of the centres by cell; members of a cell stay in increasing order.
    std::vector<std::uint32_t> cell_of(centers_.size());
    start_.assign(cells + 1, 0);
    for (std::size_t i = 0; i < centers_.size(); ++i) {
        const Vec3 c = box_.wrapped(centers_[i]);
        const std::int64_t cell =
            (axis_cell(0, c.x()) * dims_[1] + axis_cell(1, c.y())) * dims_[2] + axis_cell(2, c.z());
        cell_of[i] = static_cast<std::uint32_t>(cell);
        ++start_[static_cast<std::size_t>(cell) + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) {
        start_[c + 1] += start_[c];
    }
    members_.resize(centers_.size());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < centers_.size(); ++i) {
        members_[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
    }
}

std::array<double, 3> CellGrid::size_cells(const Vec3& span, double reach) {
    // Widen the cells until the grid holds at most 2N + 64 of them.
    const double max_cells = 2.0 * static_cast<double>(centers_.size()) + 64.0;
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
    for (int a = 0; a < 3; ++a) {
        side_[a] = wraps(a) ? span[a] / dims[a] : side;
    }
    return dims;
}

std::int64_t CellGrid::axis_cell(int a, double x) const {
    const double cell = std::floor((x - origin_[a]) / side_[a]);
    if (!(cell > 0.0)) {  // also NaN from an infinite query radius
        return 0;
    }
    const auto last = static_cast<double>(dims_[a] - 1);
    return static_cast<std::int64_t>(std::min(cell, last));
}

void CellGrid::axis_range(int a, double x, double radius, std::int64_t& lo,
                          std::int64_t& hi) const {
    if (!wraps(a)) {
        lo = axis_cell(a, x - radius);
        hi = axis_cell(a, x + radius);
        return;
    }
    // x is wrapped into the period; widened far beyond the rounding of a centre's cell.
    const double wide = radius * (1.0 + 1e-12) + side_[a] * static_cast<double>(dims_[a]) * 1e-12;
    const double first = std::floor((x - wide - origin_[a]) / side_[a]);
    const double last = std::floor((x + wide - origin_[a]) / side_[a]);
    if (!(last - first + 1.0 < static_cast<double>(dims_[a]))) {  // also NaN, infinities
        lo = 0;
        hi = dims_[a] - 1;
        return;
    }
    lo = static_cast<std::int64_t>(first);
    hi = static_cast<std::int64_t>(last);
}

std::vector<Neighbour> CellGrid::nearest(const Vec3& p, std::size_t k) const {
    std::vector<Neighbour> found;
    k = std::min(k, centers_.size());
    if (k == 0) {
        return found;
    }
    double radius = side_[1];
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
