#include "sgmp/compare/overlaps.hpp"

#include <algorithm>

#include "sgmp/compare/column_grid.hpp"
#include "sgmp/compare/pair_kernels.hpp"
#include "sgmp/compare/parallel.hpp"
#include "sgmp/pack/pack_overlaps.hpp"

namespace sgmp::compare {
namespace {

// Grid columns per parallel work item: fixed, so the depth sums do not depend on the
// thread count.
constexpr std::size_t kColumnsPerChunk = 16;

struct Tally {
    std::int64_t count = 0;
    std::int64_t count_any = 0;
    double sum = 0.0;
    double max = 0.0;
    std::vector<OverlapRecord> worst;
};

void keep_worst(std::vector<OverlapRecord>& records, std::size_t limit);

void merge(Tally& total, const Tally& part, std::size_t limit) {
    total.count += part.count;
    total.count_any += part.count_any;
    total.sum += part.sum;
    total.max = std::max(total.max, part.max);
    total.worst.insert(total.worst.end(), part.worst.begin(), part.worst.end());
    if (total.worst.size() > 4 * limit + 16) {
        keep_worst(total.worst, limit);
    }
}

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

/// Every pair once, from its earlier member in a grid of whole columns of side 2·r_max
/// over all centres (ColumnGrid::for_each_window), searched within 2·r_max: an overlap
/// needs |c_i − c_j| < r_i + r_j. The depth is computed as the pack library's overlap
/// search does, so the same pairs count.
Tally pair_overlaps(const std::vector<Particle>& particles, double mean_diameter, double floor,
                    std::size_t limit) {
    const double r_max = max_radius(particles);
    if (particles.size() < 2 || !(r_max > 0.0)) {
        return {};
    }
    const double reach = 2.0 * r_max;
    const ColumnGrid grid(particles, reach, true);
    const double reach_squared = reach * reach * (1.0 + 1e-9);  // the exact test decides
    const auto pairs_from = [&](Tally& tally, std::size_t p, std::size_t from, std::size_t to) {
        const Particle& a = particles[grid.index[p]];
        const double c[3] = {grid.x[p], grid.y[p], grid.z[p]};
        for_each_within(grid.x.data(), grid.y.data(), grid.z.data(), c, from, to, reach_squared,
                        [&](std::size_t m, double) {
                            const Particle& b = particles[grid.index[m]];
                            const double depth = a.radius + b.radius - (a.center - b.center).norm();
                            if (depth > 0.0) {
                                add(tally,
                                    OverlapRecord{std::min(a.id, b.id), std::max(a.id, b.id),
                                                  depth / mean_diameter},
                                    floor, limit);
                            }
                        });
    };
    return chunked_reduce(
        grid.columns(), kColumnsPerChunk, Tally{},
        [&](Tally& tally, std::size_t first, std::size_t last) {
            for (std::size_t column = first; column < last; ++column) {
                const std::size_t begin = grid.column_begin(column);
                const std::size_t end = grid.column_begin(column + 1);
                if (begin == end) {
                    continue;
                }
                grid.for_each_window(
                    grid, begin, end, grid.footprint(begin, end), reach, column,
                    [&](std::size_t c, std::size_t p, std::size_t from, std::size_t to) {
                        pairs_from(tally, p, c == column ? std::max(from, p + 1) : from, to);
                    });
            }
        },
        [&](Tally& total, const Tally& part) { merge(total, part, limit); });
}

}  // namespace

OverlapStats measure_overlaps(const std::vector<Particle>& particles, const Container& container,
                              double mean_diameter, double floor, std::size_t worst_count) {
    Tally walls;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const double depth = container.penetration(particles[i].center, particles[i].radius);
        if (depth > 0.0) {
            add(walls, OverlapRecord{particles[i].id, -1, depth / mean_diameter}, floor,
                worst_count);
        }
    }
    OverlapStats stats;
    stats.floor = floor;
    stats.pairs =
        summarise(pair_overlaps(particles, mean_diameter, floor, worst_count), worst_count);
    stats.walls = summarise(std::move(walls), worst_count);
    return stats;
}

}  // namespace sgmp::compare
