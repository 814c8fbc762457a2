#include "sgmp/compare/overlaps.hpp"

#include <algorithm>

#include "sgmp/pack/pack_overlaps.hpp"

namespace sgmp::compare {
namespace {

struct Tally {
    std::int64_t count = 0;
    std::int64_t count_any = 0;
    double sum = 0.0;
    double max = 0.0;
    std::vector<OverlapRecord> worst;
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

void add(Tally& tally, const OverlapRecord& record, double floor, std::size_t limit) {
    ++tally.count_any;
    tally.max = std::max(tally.max, record.depth_over_d);
    if (record.depth_over_d > floor) {
        ++tally.count;
        tally.sum += record.depth_over_d;
    }
    tally.worst.push_back(record);
    if (tally.worst.size() > 4 * limit + 16) {
        keep_worst(tally.worst, limit);
    }
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
            const std::int64_t a = particles[i].id;
            const std::int64_t b = particles[j].id;
            add(pairs, OverlapRecord{std::min(a, b), std::max(a, b), depth / mean_diameter}, floor,
                worst_count);
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

}  // namespace sgmp::compare
