#pragma once
// LIGGGHTS' result read back and checked (pour_result.cpp), for the pour (pour.cpp).
#include <filesystem>

#include "sgmp/pack/pack.hpp"
#include "sgmp/reference/pour.hpp"

namespace sgmp::reference::detail {

/// The pack of LIGGGHTS' final dump `dump`: its `p.count` spheres at rest (check_at_rest),
/// ids 1..N in order, each of one species' radius; throws PourError otherwise.
Pack read_final(const std::filesystem::path& dump, const PourParams& p);

/// A settled pour's invariants, checked before anything is written: every sphere inside
/// the container and no pair overlapping by more than the soft-contact bound (all spheres
/// present and ids 1..N are checked by read_final). A DEM blow-up or a corrupt dump fails
/// here instead of entering the reference set.
void check_settled(const PourResult& result);

}  // namespace sgmp::reference::detail
