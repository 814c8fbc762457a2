#pragma once
/// @file spatial_order.hpp
/// Groups of nearby points for batched neighbour queries: points are sorted along a
/// Morton (Z-order) curve of cubic cells and cut into consecutive groups. One kd-tree
/// query around a group's bounding box (radius + half its diagonal) returns a superset of
/// every member's neighbours; members then re-check exact distances over that short list.
/// Group boundaries depend only on the input, so results do not depend on thread count.

#include <vector>

#include "sgmp/compare/neighbour_index.hpp"

namespace sgmp::compare {

/// `subset` (indices into `points`) sorted by the Morton code of their cell of side `cell`.
std::vector<Index> spatial_order(const std::vector<Particle>& points, std::vector<Index> subset,
                                 double cell);

struct QueryGroup {
    std::size_t begin = 0;  // range in the ordered index list
    std::size_t end = 0;
    Vec3 center = Vec3::Zero();
    double half_diagonal = 0.0;
};

/// Consecutive groups of at most `size` entries of `ordered`, with their bounding boxes.
std::vector<QueryGroup> query_groups(const std::vector<Particle>& points,
                                     const std::vector<Index>& ordered, std::size_t size);

/// Candidates of one group (coordinates and radii copied contiguously for fast loops).
struct Candidates {
    std::vector<Index> index;
    std::vector<double> x, y, z, r;

    /// Fills from the kd-tree: every point within `radius` of some member of `group`
    /// is included (the query sphere covers the group's box widened by `radius`).
    void gather(const NeighbourIndex& tree, const std::vector<Particle>& points,
                const QueryGroup& group, double radius);
};

}  // namespace sgmp::compare
