#pragma once
/// @file pack_checks.hpp
/// Checks of a settled pack: the largest pair overlap max(0, ri + rj − |ci − cj|) (found
/// with a cell grid of side 2·r_max, so only neighbouring cells are compared) and the
/// largest penetration of a wall or the floor.

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/pack.hpp"

namespace sgmp::reference {

struct OverlapSummary {
    double max_overlap = 0.0;  ///< largest pair overlap (length)
    std::size_t overlapping_pairs = 0;
};

OverlapSummary pair_overlaps(const Pack& pack);

/// Largest distance by which a sphere crosses a wall or the floor (0 when none does).
double max_wall_penetration(const Pack& pack, const Container& container);

}  // namespace sgmp::reference
