#include "sgmp/metrics/overlaps.hpp"

#include <algorithm>

#include "sgmp/pack/pack_overlaps.hpp"

namespace sgmp::metrics {
namespace {

struct Tally {
    std::int64_t count = 0;
    std::int64_t count_any = 0;
    double sum = 0.0;
    double max = 0.0;
    std::vector<OverlapRecord> worst;
    // Once `worst` was cut to the limit, its last record: a record not deeper than it
    // can never be among the deepest, so it is not kept (the same deepest either way).
    bool has_cutoff = false;
    OverlapRecord cutoff{};
};

bool deeper(const OverlapRecord& a, const OverlapRecord& b) {
    if (a.depth_over_d != b.depth_over_d) {
        return a.depth_over_d > b.depth_over_d;
    }
    if (a.id_a != b.id_a) {
        return a.id_a < b.id_a;
    }
    return a.id_b < b.id_b;
}

void keep_worst(std::vector<OverlapRecord>& records, std::size_t limit) {
    std::sort(records.begin(), records.end(), deeper);
    if (records.size() > limit) {
        records.resize(limit);
    }
}

/// Counts one positive depth (over d) and keeps its record among the deepest; `record()`
/// makes the record (ids), called only when it may be among them.
template <class MakeRecord>
void add_depth(Tally& tally, double depth_over_d, double floor, std::size_t limit,
               MakeRecord&& record) {
    ++tally.count_any;
    tally.max = std::max(tally.max, depth_over_d);
    if (depth_over_d > floor) {
        ++tally.count;
        tally.sum += depth_over_d;
    }
    if (tally.has_cutoff && depth_over_d < tally.cutoff.depth_over_d) {
        return;  // not deeper than the cutoff, whatever the ids
    }
    const OverlapRecord r = record();
    if (tally.has_cutoff && !deeper(r, tally.cutoff)) {
        return;
    }
    tally.worst.push_back(r);
    if (tally.worst.size() > 4 * limit + 16) {
        keep_worst(tally.worst, limit);
        if (limit > 0 && tally.worst.size() == limit) {
            tally.has_cutoff = true;
            tally.cutoff = tally.worst.back();
        }
    }
}

void add(Tally& tally, const OverlapRecord& record, double floor, std::size_t limit) {
    add_depth(tally, record.depth_over_d, floor, limit, [&] { return record; });
}

OverlapSummary summarise(Tally tally, std::size_t limit) {
    keep_worst(tally.worst, limit);
    OverlapSummary summary;
    summary.count = tally.count;
    summary.count_any = tally.count_any;
    summary.max_over_d = tally.max;
    summary.mean_over_d = tally.count > 0 ? tally.sum / static_cast<double>(tally.count) : 0.0;
    summary.worst = std::move(tally.worst);
    return summary;
}

}  // namespace

OverlapStats measure_overlaps(const std::vector<Particle>& particles, const Container& container,
                              double mean_diameter, double floor, std::size_t worst_count) {
    Tally pairs;
    Tally walls;
    for_each_overlap(
        particles, container,
        [&](std::size_t i, std::size_t j, double depth) {
            add_depth(pairs, depth / mean_diameter, floor, worst_count, [&] {
                const std::int64_t a = particles[i].id;
                const std::int64_t b = particles[j].id;
                return OverlapRecord{std::min(a, b), std::max(a, b), depth / mean_diameter};
            });
        },
        [&](std::size_t i, double depth) {
            add(walls, OverlapRecord{particles[i].id, -1, depth / mean_diameter}, floor,
                worst_count);
        });
    OverlapStats stats;
    stats.floor = floor;
    stats.pairs = summarise(std::move(pairs), worst_count);
    stats.walls = summarise(std::move(walls), worst_count);
    return stats;
}

}  // namespace sgmp::metrics
