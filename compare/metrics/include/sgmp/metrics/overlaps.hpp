#pragma once
/// @file overlaps.hpp
/// Overlaps of a whole pack. A pair overlaps by max(0, r_i + r_j − |c_i − c_j|) (each
/// pair's own radii); a particle overlaps a wall or the floor by how far its sphere
/// crosses it (Container::penetration). Depths are reported over the mean diameter d.
/// Pairs and walls deeper than `floor`·d are counted; `*_any` counts every positive depth
/// (touching spheres placed in floating point may overlap by ~1e-16·d).

#include <cstdint>
#include <vector>

#include "sgmp/pack/particle.hpp"

#include "sgmp/pack/geometry.hpp"

namespace sgmp::metrics {

struct OverlapRecord {
    std::int64_t id_a = 0;
    std::int64_t id_b = -1;  // -1: a wall or the floor
    double depth_over_d = 0.0;
};

struct OverlapSummary {
    std::int64_t count = 0;      // deeper than floor·d
    std::int64_t count_any = 0;  // any positive depth
    double max_over_d = 0.0;
    double mean_over_d = 0.0;          // over the counted ones; 0 when none
    std::vector<OverlapRecord> worst;  // deepest first, ties by ids
};

struct OverlapStats {
    double floor = 0.0;  // counting threshold, over d
    OverlapSummary pairs;
    OverlapSummary walls;
};

/// Overlaps between all particles and against the container, found by the project's one
/// overlap search (sgmp/pack/pack_overlaps.hpp: every part counts the same pairs at the same
/// depths), in parallel work items of fixed size folded in order (so the depth sum is the
/// same for any thread count).
OverlapStats measure_overlaps(const std::vector<Particle>& particles, const Container& container,
                              double mean_diameter, double floor, std::size_t worst_count,
                              unsigned threads = 0);

}  // namespace sgmp::metrics
