#include "sgmp/compare/overlaps.hpp"

#include <algorithm>

#include "sgmp/compare/parallel.hpp"
#include "sgmp/compare/spatial_order.hpp"

#include <cmath>

namespace sgmp::compare {
namespace {

// One particle per query: at a radius of one diameter, grouping costs more than it saves.
constexpr std::size_t kGroupSize = 1;
constexpr std::size_t kGroupsPerChunk = 4096;

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
    std::vector<Index> all(particles.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        all[i] = static_cast<Index>(i);
    }
    const std::vector<Index> ordered = spatial_order(particles, std::move(all), mean_diameter);
    const std::vector<QueryGroup> groups = query_groups(particles, ordered, kGroupSize);
    const double reach = 2.0 * max_radius;
    const Both both = chunked_reduce(
        groups.size(), kGroupsPerChunk, Both{},
        [&](Both& part, std::size_t begin, std::size_t end) {
            Candidates candidates;
            for (std::size_t g = begin; g < end; ++g) {
                candidates.gather(index, particles, groups[g], reach);
                for (std::size_t o = groups[g].begin; o < groups[g].end; ++o) {
                    const Index i = ordered[o];
                    const Particle& a = particles[i];
                    for (std::size_t k = 0; k < candidates.index.size(); ++k) {
                        const Index j = candidates.index[k];
                        if (j <= i) {
                            continue;
                        }
                        const double dx = candidates.x[k] - a.center.x();
                        const double dy = candidates.y[k] - a.center.y();
                        const double dz = candidates.z[k] - a.center.z();
                        const double sum = a.radius + candidates.r[k];
                        const double squared = dx * dx + dy * dy + dz * dz;
                        if (squared >= sum * sum) {
                            continue;
                        }
                        const double depth = sum - std::sqrt(squared);
                        if (depth > 0.0) {
                            const Particle& b = particles[j];
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
