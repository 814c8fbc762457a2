#pragma once
/// @file neighbour_list.hpp
/// Verlet neighbour list of the relaxation: for each sphere i, the spheres j > i whose
/// surface gap |cᵢ − cⱼ| − rᵢ − rⱼ was below `skin` when the list was built. While no sphere
/// has moved more than skin/2 since, every touching pair is in the list. Built through a
/// cell list over the spheres' bounding box (cells of side ≥ 2·r_max + skin, counting sort,
/// the 27 cells around each sphere), in O(N); the scan order is fixed, so the same positions
/// give the same list. With periodic sides (Container::periodic) the cells wrap in x and z
/// and pairs are minimum-image pairs (Container::to_nearest_image), so the pair loops must
/// take the nearest image of each listed pair's separation too.
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
    /// Rebuilds the list for the spheres' present positions; only `sides.periodic` and, when
    /// set, its periods are read (the cell must be over twice 2·r_max + skin wide).
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
    // Scratch of the cell list, kept to reuse its memory.
    std::vector<std::uint32_t> cell_of_;
    std::vector<std::uint32_t> cell_start_;
    std::vector<std::uint32_t> by_cell_;
};

}  // namespace sgmp::engine
