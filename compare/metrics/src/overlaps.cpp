#include "sgmp/metrics/overlaps.hpp"

#include <algorithm>

#include "sgmp/metrics/parallel.hpp"
#include "sgmp/pack/pack_overlaps.hpp"
#include "sgmp/pack/periodic_images.hpp"

namespace sgmp::metrics {
namespace {

/// Spheres per parallel work item of the pair search: fixed, so sums do not depend on the
/// thread count.
constexpr std::size_t kSpheresPerChunk = 8192;

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
                              double mean_diameter, double floor, std::size_t worst_count,
                              unsigned threads) {
    // The pairs in work items of fixed size, folded in order: the depth sum is the same
    // for any thread count. With periodic sides, minimum-image pairs through the images
    // (periodic_images.hpp), each once.
    const ImagedParticles imaged =
        with_periodic_images(particles, container, 2.0 * max_radius(particles));
    const OverlapSearch search(imaged.particles);
    const Tally pairs = chunked_reduce(
        threads, particles.size(), kSpheresPerChunk, Tally{},
        [&](Tally& tally, std::size_t first, std::size_t last) {
            search.pairs_from(first, last, [&](std::size_t i, std::size_t image, double depth) {
                const std::size_t j = imaged.source[image];
                if (image >= imaged.originals && !(i < j)) {
                    return;  // met as (j, image of i)
                }
                add_depth(tally, depth / mean_diameter, floor, worst_count, [&] {
                    const std::int64_t a = particles[i].id;
                    const std::int64_t b = particles[j].id;
                    return OverlapRecord{std::min(a, b), std::max(a, b), depth / mean_diameter};
                });
            });
        },
        [&](Tally& total, const Tally& part) { merge(total, part, worst_count); });
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
    stats.pairs = summarise(pairs, worst_count);
    stats.walls = summarise(std::move(walls), worst_count);
    return stats;
}

}  // namespace sgmp::metrics
