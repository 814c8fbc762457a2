#include "sgmp/compare/overlaps.hpp"

#include <algorithm>

#include "sgmp/compare/parallel.hpp"

#include <cmath>

namespace sgmp::compare {
namespace {

constexpr std::size_t kChunk = 4096;

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

void fold(Tally& total, const Tally& part, std::size_t limit) {
    total.count += part.count;
    total.count_any += part.count_any;
    total.sum += part.sum;
    total.max = std::max(total.max, part.max);
    total.worst.insert(total.worst.end(), part.worst.begin(), part.worst.end());
    keep_worst(total.worst, limit);
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

OverlapStats measure_overlaps(const std::vector<Particle>& particles, const NeighbourIndex& index,
                              const Container& container, double mean_diameter, double floor,
                              std::size_t worst_count) {
    double max_radius = 0.0;
    for (const Particle& p : particles) {
        max_radius = std::max(max_radius, p.radius);
    }
    struct Both {
        Tally pairs;
        Tally walls;
    };
    // One query per particle, in index order (measure() orders particles along a Morton
    // curve, which keeps consecutive queries in cache).
    const double reach = 2.0 * max_radius;
    const Both both = chunked_reduce(
        particles.size(), kChunk, Both{},
        [&](Both& part, std::size_t begin, std::size_t end) {
            std::vector<Index> found;
            for (std::size_t i = begin; i < end; ++i) {
                const Particle& a = particles[i];
                index.within(a.center, std::min(reach, a.radius + max_radius), found);
                for (const Index j : found) {
                    if (j <= i) {
                        continue;
                    }
                    const Particle& b = particles[j];
                    const double depth = a.radius + b.radius - (a.center - b.center).norm();
                    if (depth > 0.0) {
                        add(part.pairs,
                            OverlapRecord{std::min(a.id, b.id), std::max(a.id, b.id),
                                          depth / mean_diameter},
                            floor, worst_count);
                    }
                }
                const double wall = container.penetration(a.center, a.radius);
                if (wall > 0.0) {
                    add(part.walls, OverlapRecord{a.id, -1, wall / mean_diameter}, floor,
                        worst_count);
                }
            }
        },
        [&](Both& total, const Both& part) {
            fold(total.pairs, part.pairs, worst_count);
            fold(total.walls, part.walls, worst_count);
        });
    OverlapStats stats;
    stats.floor = floor;
    stats.pairs = summarise(both.pairs, worst_count);
    stats.walls = summarise(both.walls, worst_count);
    return stats;
}

}  // namespace sgmp::compare
