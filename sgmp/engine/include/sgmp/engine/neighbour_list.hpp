#pragma once
/// @file neighbour_list.hpp
/// Verlet neighbour list of the relaxation: for each sphere i, the spheres j > i whose
/// surface gap |cᵢ − cⱼ| − rᵢ − rⱼ was below `skin` when the list was built, in increasing j.
/// While no sphere has moved more than skin/2 since, every touching pair is in the list.
/// Built through the neighbour-query vocabulary's cell grid (sgmp/pack/cell_grid.hpp: every
/// pair within 2·r_max + skin, O(N)), then each pair kept at its own reach; the list's
/// order is the pairs' (i, j) order, whatever the grid, so the same positions give the same
/// list. With periodic sides (Container::periodic) pairs are nearest-image pairs
/// (NeighbourBox::separation), so the pair loops must take the nearest image of each listed
/// pair's separation too.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "sgmp/pack/geometry.hpp"

namespace sgmp::engine {

/// A sphere's centre and radius, together in 32 bytes (one cache line holds two).
struct Ball {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    double r = 0.0;
};

class NeighbourList {
  public:
    /// Rebuilds the list for the spheres' present positions (finite, else
    /// std::invalid_argument); only `sides.periodic` and, when set, its periods are read.
    void build(const std::vector<Ball>& balls, double skin, const Container& sides = {});

    /// The neighbours j > i of sphere i.
    [[nodiscard]] std::span<const std::uint32_t> of(std::size_t i) const {
        return {neighbours_.data() + offsets_[i], neighbours_.data() + offsets_[i + 1]};
    }
    [[nodiscard]] std::size_t pairs() const { return neighbours_.size(); }
    /// Position of i's first neighbour in the list of all pairs (the pairs are stored i by i).
    [[nodiscard]] std::size_t first_slot(std::size_t i) const { return offsets_[i]; }

  private:
    std::vector<std::uint32_t> offsets_;
    std::vector<std::uint32_t> neighbours_;
    std::vector<Vec3> centers_;  ///< scratch: the centres handed to the grid
};

}  // namespace sgmp::engine
