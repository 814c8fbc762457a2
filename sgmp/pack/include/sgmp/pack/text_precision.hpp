#pragma once
/// @file text_precision.hpp
/// Overlaps that come only from the text precision of a pack file.
///
/// A number written with D decimals is within h = 0.5·10^-D of the value it was rounded
/// from. The surface gap g = |ci − cj| − ri − rj of two spheres is then within
/// ε = (√3 + 1)·10^-D of the gap before rounding: each coordinate of ci − cj moves by at
/// most 2h = 10^-D, so the distance by at most √3·10^-D, and ri + rj by at most 10^-D. An
/// overlapping pair (|ci − cj| < ri + rj) whose overlap ri + rj − |ci − cj| is at most ε may
/// have been touching or apart before the file was written (ASE, for one, writes 8
/// decimals; a hard-sphere pack full of contacts then reads back with overlaps).
///
/// As in the metrics (compare/README.md), only overlaps deeper than a floor count: spheres
/// placed touching in floating point may overlap by ~1e-16 d; callers pass 1e-9 d.

#include <cstddef>
#include <vector>

#include "sgmp/pack/particle.hpp"

namespace sgmp {

struct PrecisionOverlaps {
    /// All pairs overlapping by more than the floor.
    std::size_t overlaps = 0;
    /// Those with overlap ≤ bound, and the largest such overlap.
    std::size_t within_precision = 0;
    double max_overlap = 0.0;
    /// ε = (√3 + 1)·10^-decimals.
    double bound = 0.0;
};

/// Pairs found by the one overlap search of the pack library (pack_overlaps.hpp), depths
/// (r_i + r_j) − |c_i − c_j|.
PrecisionOverlaps precision_overlaps(const std::vector<Particle>& particles, int decimals,
                                     double floor);

}  // namespace sgmp
