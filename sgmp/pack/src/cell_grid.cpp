#include "sgmp/pack/cell_grid.hpp"

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

CellGrid::CellGrid(const std::vector<Vec3>& centers, double reach)
    : centers_(centers), reach_(reach) {
    if (!(reach > 0.0) || !std::isfinite(reach)) {
        throw std::invalid_argument("cell grid: reach must be a positive finite length");
    }
    if (centers_.size() >= std::numeric_limits<std::uint32_t>::max()) {
        throw std::invalid_argument("cell grid: too many centres");
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
    origin_ = lo;
    const Vec3 span = hi - lo;
    // Widen the cells until the grid holds at most 2N + 64 of them.
    const double max_cells = 2.0 * static_cast<double>(centers_.size()) + 64.0;
    side_ = reach;
    if (!span.allFinite()) {
        side_ = INFINITY;  // centres near ±10³⁰⁸: one cell (every query still exact)
    }
    while (std::isfinite(side_) && cell_count(dims_for(span, side_)) > max_cells) {
        side_ *= 1.25;
    }
    const std::array<double, 3> dims =
        std::isfinite(side_) ? dims_for(span, side_) : std::array<double, 3>{1.0, 1.0, 1.0};
    for (int a = 0; a < 3; ++a) {
        dims_[a] = static_cast<std::int64_t>(dims[a]);  // at most 2N + 64 by now
    }
    const auto cells = static_cast<std::size_t>(cell_count(dims));

    // Counting sort of the centres by cell; members of a cell stay in increasing order.
    std::vector<std::uint32_t> cell_of(centers_.size());
    start_.assign(cells + 1, 0);
    for (std::size_t i = 0; i < centers_.size(); ++i) {
        const Vec3& c = centers_[i];
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

std::int64_t CellGrid::axis_cell(int a, double x) const {
    const double cell = std::floor((x - origin_[a]) / side_);
    if (!(cell > 0.0)) {  // also NaN from an infinite query radius
        return 0;
    }
    const auto last = static_cast<double>(dims_[a] - 1);
    return static_cast<std::int64_t>(std::min(cell, last));
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
