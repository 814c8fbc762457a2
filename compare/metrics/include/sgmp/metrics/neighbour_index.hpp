#pragma once
/// @file neighbour_index.hpp
/// The metrics' implementation of the neighbour-query vocabulary
/// (sgmp/pack/neighbour_query.hpp) on CGAL's kd-tree (Spatial_searching, Simple_cartesian
/// <double>), through CGAL's own queries: radius queries by Fuzzy_sphere, made slightly
/// wider than asked (CGAL may or may not report points exactly on the sphere's boundary),
/// every candidate re-checked exactly; k nearest by Orthogonal_k_neighbor_search, whose
/// k-th distance then bounds one exact radius query (so ties are broken by index, as the
/// vocabulary says). In a periodic box the tree holds the wrapped points and a query also
/// asks from the images of its point one period away in x, z or both, where the query's
/// sphere meets the cell.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "sgmp/pack/neighbour_query.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::metrics {

using Index = std::uint32_t;

class NeighbourIndex {
  public:
    explicit NeighbourIndex(const std::vector<Vec3>& points,
                            const NeighbourBox& box = NeighbourBox::open());
    /// The index of the particles' centres.
    explicit NeighbourIndex(const std::vector<Particle>& particles,
                            const NeighbourBox& box = NeighbourBox::open());
    ~NeighbourIndex();
    NeighbourIndex(const NeighbourIndex&) = delete;
    NeighbourIndex& operator=(const NeighbourIndex&) = delete;

    [[nodiscard]] std::size_t size() const;
    [[nodiscard]] const NeighbourBox& box() const;

    /// Replaces `out` with the indices of the points p with |p − q| ≤ radius (the box's
    /// distance), each once, in no particular order. `out` is a buffer the caller may reuse
    /// between queries.
    void within(const Vec3& q, double radius, std::vector<Index>& out) const;

    /// Replaces `out` with the points within `radius` of q (NeighbourBox::distance2 ≤
    /// radius²) and their squared distances, each once, in no particular order.
    void neighbours_within(const Vec3& q, double radius, std::vector<Neighbour>& out) const;

    /// The vocabulary (NeighbourQuery): f(j, d²) for the points within `radius` of p.
    template <class F>
    void for_each_within(const Vec3& p, double radius, F&& f) const {
        std::vector<Neighbour> found;
        neighbours_within(p, radius, found);
        for (const Neighbour& n : found) {
            f(n.index, n.distance2);
        }
    }

    /// f(i, j, d²) for every pair i < j within `radius`, by increasing i, then j.
    template <class F>
    void for_each_pair_within(double radius, F&& f) const {
        std::vector<Neighbour> found;
        for (std::size_t i = 0; i < size(); ++i) {
            neighbours_within(point(i), radius, found);
            std::sort(found.begin(), found.end(),
                      [](const Neighbour& a, const Neighbour& b) { return a.index < b.index; });
            for (const Neighbour& n : found) {
                if (n.index > i) {
                    f(i, n.index, n.distance2);
                }
            }
        }
    }

    /// The min(k, size()) points nearest q, by distance, then index.
    [[nodiscard]] std::vector<Neighbour> nearest(const Vec3& q, std::size_t k) const;

    /// Point i as given.
    [[nodiscard]] const Vec3& point(std::size_t i) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace sgmp::metrics
