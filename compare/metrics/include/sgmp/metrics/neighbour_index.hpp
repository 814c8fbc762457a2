#pragma once
/// @file neighbour_index.hpp
/// Fixed-radius neighbour search on CGAL's kd-tree (Spatial_searching, Simple_cartesian
/// <double>): points carry their index, a fuzzy-sphere query is made slightly wider than
/// asked (CGAL may or may not report points exactly on the sphere's boundary) and every
/// candidate is re-checked exactly: |p − q|² ≤ radius².

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "sgmp/pack/particle.hpp"

namespace sgmp::metrics {

using Index = std::uint32_t;

class NeighbourIndex {
  public:
    explicit NeighbourIndex(const std::vector<Vec3>& points);
    /// The index of the particles' centres (no copy of them is kept besides the tree's).
    explicit NeighbourIndex(const std::vector<Particle>& particles);
    ~NeighbourIndex();
    NeighbourIndex(const NeighbourIndex&) = delete;
    NeighbourIndex& operator=(const NeighbourIndex&) = delete;

    [[nodiscard]] std::size_t size() const;

    /// Replaces `out` with the indices of the points p with |p − q| ≤ radius, in no
    /// particular order. `out` is a buffer the caller may reuse between queries.
    void within(const Vec3& q, double radius, std::vector<Index>& out) const;

    /// The rank of each point in the tree's report order: every query reports the points
    /// it finds in increasing rank (the tree is walked lower child first, leaves in their
    /// stored order). Sorting by rank reproduces a query's order without the tree.
    [[nodiscard]] std::vector<Index> report_rank() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Every pair (i, j), i < j, with |p_i − p_j| ≤ cutoff, sorted.
std::vector<std::pair<Index, Index>> pairs_within(const std::vector<Vec3>& points, double cutoff,
                                                  unsigned threads = 0);

}  // namespace sgmp::metrics
