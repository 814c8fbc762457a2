#pragma once
/// @file neighbour_query.hpp
/// The testbed's one neighbour-query vocabulary (after freud's NeighborQuery): a set of
/// points in a box, asked for the points within a radius of a point, for every pair within
/// a radius, and for the k nearest points of a point.
///
/// The box is open (walls: space is unbounded for the search, the container's walls are
/// its users' business) or periodic in x and z with the periods of a pack's periodic sides
/// (Container::periodic); y is never periodic. In a periodic box the distance of two points
/// is the distance of their nearest images (NeighbourBox::distance2), and every query meets
/// each point at most once, at that distance, whatever the radius.
///
/// Radii are inclusive: a point at distance exactly r is within r. Two implementations
/// satisfy NeighbourQuery: the cell grid of the pack library (`CellGrid`, cell_grid.hpp)
/// and the CGAL kd-tree of the metrics (`metrics::NeighbourIndex`, neighbour_index.hpp);
/// tests/pack/neighbour_query_test.cpp and tests/compare/neighbour_implementations_test.cpp
/// check both against brute force over this header's distance, open and periodic.
#include <cmath>
#include <concepts>
#include <cstddef>
#include <vector>

#include "sgmp/pack/geometry.hpp"

namespace sgmp {

/// The space a neighbour query searches: open, or periodic in x and z.
struct NeighbourBox {
    bool periodic = false;  ///< x and z periodic (then the bounds below are the periods')
    double x_min = 0.0;
    double x_max = 0.0;
    double z_min = 0.0;
    double z_max = 0.0;

    /// Open space (the default).
    static NeighbourBox open() { return {}; }
    /// The space of a pack in `container`: periodic in x and z when its sides are, else open.
    static NeighbourBox of(const Container& container) {
        if (!container.periodic) {
            return open();
        }
        return {true, container.x_min, container.x_max, container.z_min, container.z_max};
    }
    [[nodiscard]] double period_x() const { return x_max - x_min; }
    [[nodiscard]] double period_z() const { return z_max - z_min; }

    /// The point moved by whole periods into [x_min, x_max) × [z_min, z_max) when periodic
    /// (Container::wrapped); unchanged otherwise.
    [[nodiscard]] Vec3 wrapped(const Vec3& p) const {
        if (!periodic) {
            return p;
        }
        Container sides;
        sides.x_min = x_min;
        sides.x_max = x_max;
        sides.z_min = z_min;
        sides.z_max = z_max;
        sides.periodic = true;
        return sides.wrapped(p);
    }

    /// to − from, its x and z moved by whole periods to the nearest image when periodic
    /// (the arithmetic of Container::to_nearest_image).
    [[nodiscard]] Vec3 separation(const Vec3& from, const Vec3& to) const {
        Vec3 d = to - from;
        if (periodic) {
            d.x() -= period_x() * std::nearbyint(d.x() / period_x());
            d.z() -= period_z() * std::nearbyint(d.z() / period_z());
        }
        return d;
    }

    /// Squared distance of a and b (of their nearest images when periodic); the one
    /// distance every implementation and every brute-force oracle compares with r².
    [[nodiscard]] double distance2(const Vec3& a, const Vec3& b) const {
        if (!periodic) {
            return (b - a).squaredNorm();
        }
        return separation(a, b).squaredNorm();
    }
};

/// A point met by a query: its index and squared distance.
struct Neighbour {
    std::size_t index = 0;
    double distance2 = 0.0;
    friend bool operator==(const Neighbour&, const Neighbour&) = default;
};

/// Orders neighbours by distance, then index: the order of `nearest`.
inline bool nearer(const Neighbour& a, const Neighbour& b) {
    return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.index < b.index);
}

/// The vocabulary:
/// - `size()`: the number of points; `box()`: their box;
/// - `for_each_within(p, r, f)`: f(j, d²) once for every point j with d² ≤ r² (d the
///   box's distance from p), in the implementation's order;
/// - `for_each_pair_within(r, f)`: f(i, j, d²) once for every pair i < j with d² ≤ r²;
/// - `nearest(p, k)`: the min(k, size()) points nearest p, by distance, then index.
template <class Q>
concept NeighbourQuery = requires(const Q& q, const Vec3& p, double r, std::size_t k,
                                  void (*on_point)(std::size_t, double),
                                  void (*on_pair)(std::size_t, std::size_t, double)) {
    { q.size() } -> std::convertible_to<std::size_t>;
    { q.box() } -> std::convertible_to<NeighbourBox>;
    q.for_each_within(p, r, on_point);
    q.for_each_pair_within(r, on_pair);
    { q.nearest(p, k) } -> std::same_as<std::vector<Neighbour>>;
};

}  // namespace sgmp
