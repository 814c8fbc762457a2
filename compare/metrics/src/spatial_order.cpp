#include "sgmp/metrics/spatial_order.hpp"

#include "sgmp/metrics/parallel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace sgmp::metrics {
namespace {

/// Spreads the low 21 bits of v so that two zero bits separate consecutive bits.
std::uint64_t spread_bits(std::uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
}

/// Sorts by (code, index): eight parts sorted on the worker threads, then merged. The
/// keys are distinct, so the result is the one sorted order whatever the thread count.
void sort_in_parts(std::vector<std::pair<std::uint64_t, Index>>& keyed, unsigned threads) {
    constexpr std::size_t kParts = 8;
    if (keyed.size() < 65536) {
        std::sort(keyed.begin(), keyed.end());
        return;
    }
    std::array<std::size_t, kParts + 1> bound{};
    for (std::size_t k = 0; k <= kParts; ++k) {
        bound[k] = keyed.size() * k / kParts;
    }
    const auto at = [&](std::size_t k) {
        return keyed.begin() + static_cast<std::ptrdiff_t>(bound[k]);
    };
    parallel_for(threads, kParts, [&](std::size_t k) { std::sort(at(k), at(k + 1)); });
    for (std::size_t width = 1; width < kParts; width *= 2) {
        parallel_for(threads, kParts / (2 * width), [&](std::size_t m) {
            const std::size_t first = 2 * width * m;
            std::inplace_merge(at(first), at(first + width), at(first + 2 * width));
        });
    }
}

/// Sorts by code with a least-significant-digit radix sort (11-bit digits, as many as the
/// largest code needs: two for the 21-bit codes of 128 cells a side). Each pass is a stable
/// counting sort in fixed parts on the worker threads (a part's keys go, in their order,
/// after those of the parts before it), so keys given in increasing index come out sorted
/// by (code, index): the same order as sort_in_parts.
void radix_sort(std::vector<std::pair<std::uint64_t, Index>>& keyed, unsigned threads) {
    constexpr int kBits = 11;
    constexpr std::size_t kDigits = std::size_t{1} << kBits;
    constexpr std::size_t kPart = 1 << 17;
    const std::size_t n = keyed.size();
    const std::size_t parts = (n + kPart - 1) / kPart;
    std::vector<std::uint64_t> tops(parts, 0);
    parallel_for(threads, parts, [&](std::size_t t) {
        for (std::size_t i = t * kPart; i < std::min(n, (t + 1) * kPart); ++i) {
            tops[t] |= keyed[i].first;
        }
    });
    std::uint64_t top = 0;
    for (const std::uint64_t t : tops) {
        top |= t;
    }
    std::vector<std::pair<std::uint64_t, Index>> other(n);
    std::vector<std::size_t> counts(parts * kDigits);
    for (int shift = 0; shift < 64 && (top >> shift) != 0; shift += kBits) {
        const auto digit = [shift](std::uint64_t code) {
            return static_cast<std::size_t>((code >> shift) & (kDigits - 1));
        };
        std::fill(counts.begin(), counts.end(), 0);
        parallel_for(threads, parts, [&](std::size_t t) {
            std::size_t* const count = counts.data() + t * kDigits;
            for (std::size_t i = t * kPart; i < std::min(n, (t + 1) * kPart); ++i) {
                ++count[digit(keyed[i].first)];
            }
        });
        std::size_t at = 0;
        for (std::size_t d = 0; d < kDigits; ++d) {  // counts become each part's first position
            for (std::size_t t = 0; t < parts; ++t) {
                const std::size_t c = counts[t * kDigits + d];
                counts[t * kDigits + d] = at;
                at += c;
            }
        }
        parallel_for(threads, parts, [&](std::size_t t) {
            std::size_t* const next = counts.data() + t * kDigits;
            for (std::size_t i = t * kPart; i < std::min(n, (t + 1) * kPart); ++i) {
                other[next[digit(keyed[i].first)]++] = keyed[i];
            }
        });
        keyed.swap(other);
    }
}

}  // namespace

std::vector<Index> spatial_order(const std::vector<Particle>& points, std::vector<Index> subset,
                                 double cell, unsigned threads) {
    if (subset.empty()) {
        return subset;
    }
    Vec3 lo = points[subset.front()].center;
    for (const Index i : subset) {
        lo = lo.cwiseMin(points[i].center);
    }
    std::vector<std::pair<std::uint64_t, Index>> keyed(subset.size());
    constexpr std::size_t kChunk = 65536;
    parallel_for(threads, (subset.size() + kChunk - 1) / kChunk, [&](std::size_t chunk) {
        const std::size_t end = std::min(subset.size(), (chunk + 1) * kChunk);
        for (std::size_t k = chunk * kChunk; k < end; ++k) {
            const Index i = subset[k];
            std::uint64_t code = 0;
            for (int axis = 0; axis < 3; ++axis) {
                const double c = std::floor((points[i].center[axis] - lo[axis]) / cell);
                const auto bits = static_cast<std::uint64_t>(std::clamp(c, 0.0, 2097151.0));
                code |= spread_bits(bits) << axis;
            }
            keyed[k] = {code, i};
        }
    });
    if (std::is_sorted(subset.begin(), subset.end())) {
        radix_sort(keyed, threads);
    } else {
        sort_in_parts(keyed, threads);
    }
    for (std::size_t k = 0; k < keyed.size(); ++k) {
        subset[k] = keyed[k].second;
    }
    return subset;
}

}  // namespace sgmp::metrics
