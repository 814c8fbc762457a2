#pragma once
/// @file pack_overlaps.hpp
/// Overlaps of a finished pack, the one search every part uses (the engine's checks, the
/// reference's checks of a pour, and compare's overlap metric).
///
/// A pair overlaps by depth (r_i + r_j) − |c_i − c_j| > 0 (each pair's own radii); a
/// sphere overlaps the container by Container::penetration > 0 (how far it crosses a
/// wall or the floor). Pairs are found on a CellGrid of reach 2·r_max: overlapping
/// centres are closer than r_i + r_j ≤ 2·r_max. A wide blend (r_max > 2·r_min) has the
/// grid's reach 2·r_s, r_s the largest radius ≤ r_max / 2 (every pair of small spheres),
/// and the few large spheres (r > r_max / 2) look for their partners beyond it within
/// r_l + r_max: cells sized for the small spheres, not for the largest.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "sgmp/pack/cell_grid.hpp"
#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/periodic_images.hpp"

namespace sgmp {

/// Largest radius of `particles` (0 when empty).
double max_radius(const std::vector<Particle>& particles);

/// The pair search: a CellGrid of reach 2·r_max over the centres (none when fewer than two
/// spheres or r_max = 0). `particles` must outlive it.
class OverlapSearch {
  public:
    explicit OverlapSearch(const std::vector<Particle>& particles);

    /// Calls on_pair(i, j, depth) for every overlapping pair i < j with first ≤ i < last,
    /// in CellGrid::for_each_pair order (a wide blend: then the pairs of a large sphere
    /// farther apart than the grid's reach, by increasing i, then j); the pairs of
    /// for_each_overlap, cut by i.
    template <class OnPair>
    void pairs_from(std::size_t first, std::size_t last, OnPair&& on_pair) const {
        if (!grid_) {
            return;
        }
        const auto report = [&](std::size_t i, std::size_t j) {
            const Particle& a = particles_[i];
            const Particle& b = particles_[j];
            const double depth = a.radius + b.radius - (a.center - b.center).norm();
            if (depth > 0.0) {
                on_pair(i, j, depth);
            }
        };
        grid_->for_each_pair_from(first, last,
                                  [&](std::size_t i, std::size_t j, double) { report(i, j); });
        const auto from = std::lower_bound(beyond_.begin(), beyond_.end(),
                                           std::pair<std::size_t, std::size_t>{first, 0});
        for (auto it = from; it != beyond_.end() && it->first < last; ++it) {
            report(it->first, it->second);
        }
    }

  private:
    const std::vector<Particle>& particles_;
    std::optional<CellGrid> grid_;
    /// A wide blend's overlapping pairs with a large sphere (r > r_max / 2) farther apart
    /// than the grid's reach, (i, j) with i < j, sorted: found once, when the search is
    /// built (few: a settled pack has few overlaps).
    std::vector<std::pair<std::size_t, std::size_t>> beyond_;
};

/// Calls on_pair(i, j, depth) for every overlapping pair i < j (indices into
/// `particles`, in CellGrid::for_each_pair order), then on_wall(i, depth) for every sphere
/// crossing the container, in index order. Depths are lengths, > 0. With periodic sides
/// (Container::periodic) pairs are minimum-image pairs (periodic_images.hpp), found after
/// the direct ones, and only the floor is a wall.
template <class OnPair, class OnWall>
void for_each_overlap(const std::vector<Particle>& particles, const Container& container,
                      OnPair&& on_pair, OnWall&& on_wall) {
    if (!container.periodic) {
        OverlapSearch(particles).pairs_from(0, particles.size(), on_pair);
    } else {
        const ImagedParticles imaged =
            with_periodic_images(particles, container, 2.0 * max_radius(particles));
        OverlapSearch(imaged.particles)
            .pairs_from(0, imaged.originals, [&](std::size_t i, std::size_t j, double depth) {
                const std::size_t k = imaged.source[j];
                if (j < imaged.originals || i < k) {
                    on_pair(i, k, depth);
                }
            });
    }
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const double depth = container.penetration(particles[i].center, particles[i].radius);
        if (depth > 0.0) {
            on_wall(i, depth);
        }
    }
}

/// Counts and deepest depths of the overlaps deeper than `tolerance` (a length ≥ 0).
struct OverlapCount {
    std::size_t pairs = 0;  ///< pairs deeper than tolerance
    double max_pair = 0.0;  ///< deepest pair (any depth), 0 when none overlaps
    std::size_t walls = 0;  ///< spheres crossing the container by more than tolerance
    double max_wall = 0.0;  ///< deepest wall or floor penetration, 0 when none
};

OverlapCount count_overlaps(const std::vector<Particle>& particles, const Container& container,
                            double tolerance);

}  // namespace sgmp
