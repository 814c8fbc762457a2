#include "sgmp/metrics/pair_kernels.hpp"

#include <cmath>

namespace sgmp::metrics {
namespace {

bool cpu_has_avx512() {
#if defined(SGMP_PAIR_KERNELS_AVX512)
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx512vl");
#else
    return false;
#endif
}

bool cpu_has_avx2() {
#if defined(SGMP_PAIR_KERNELS_AVX512)
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

const bool cpu_avx512 = cpu_has_avx512();
const bool cpu_avx2 = !cpu_avx512 && cpu_has_avx2();

/// Adds weight to split[w] when the distance lies in window w.
inline void count_split(double distance, std::int64_t weight, const BinSetup& s,
                        std::int64_t (&split)[2]) {
    for (int w = 0; w < 2; ++w) {
        split[w] += (distance >= s.split_lo[w] && distance <= s.split_hi[w]) ? weight : 0;
    }
}

#if defined(SGMP_PAIR_KERNELS_AVX512)

/// Histogram slots (lane·(bins + 1) + bin) of counted pairs, added to the lanes in bulk:
/// the counted lanes of each group of eight are packed together, so rejected candidates
/// cost no increment.
struct Slots {
    static constexpr std::size_t kCapacity = 2048;
    alignas(64) std::int32_t at[kCapacity + 8];
    alignas(64) double near_split[kCapacity + 8];  // distances that may lie in a split window
    std::size_t n = 0;
    std::size_t splits = 0;

    void flush_bins(std::int64_t* lanes, std::int64_t weight) {
        for (std::size_t i = 0; i < n; ++i) {
            lanes[at[i]] += weight;
        }
        n = 0;
    }

    void flush(std::int64_t* lanes, std::int64_t weight, const BinSetup& s,
               std::int64_t (&split)[2]) {
        flush_bins(lanes, weight);
        for (std::size_t i = 0; i < splits; ++i) {
            count_split(near_split[i], weight, s, split);
        }
        n = 0;
        splits = 0;
    }
};

SGMP_AVX512 inline __attribute__((always_inline)) void count_bins_avx512(
    const double* xs, const double* ys, const double* zs, const double (&a)[3], std::size_t from,
    std::size_t to, std::int64_t weight, const BinSetup& s, std::int64_t* lanes, Slots& slots,
    std::int64_t (&split)[2]) {
    const __m512d ax = _mm512_set1_pd(a[0]);
    const __m512d ay = _mm512_set1_pd(a[1]);
    const __m512d az = _mm512_set1_pd(a[2]);
    const __m512d reach = _mm512_set1_pd(s.reach_squared);
    const __m512d per_width = _mm512_set1_pd(s.per_width);
    const __m512d half = _mm512_set1_pd(0.5);
    const __m256i bins = _mm256_set1_epi32(static_cast<int>(s.bins));
    const __m256i split_first = _mm256_set1_epi32(static_cast<int>(s.split_first));
    const __m256i split_bins = _mm256_set1_epi32(static_cast<int>(s.split_bins));
    const auto stride = static_cast<int>(s.bins + 1);
    const __m256i lane_start =
        _mm256_mullo_epi32(_mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7), _mm256_set1_epi32(stride));
    // The fill levels in registers: the buffers' vector stores may alias any memory.
    std::size_t n = slots.n;
    std::size_t splits = slots.splits;
    std::int32_t* const at = slots.at;
    double* const near_split = slots.near_split;
    for (std::size_t k = from; k < to; k += 8) {
        const std::size_t left = to - k;
        const __mmask8 live = left >= 8 ? __mmask8(0xff) : __mmask8((1u << left) - 1u);
        const __m512d dx = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, xs + k), ax);
        const __m512d dy = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, ys + k), ay);
        const __m512d dz = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, zs + k), az);
        const __m512d q = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)),
                                        _mm512_mul_pd(dz, dz));
        const __mmask8 near = _mm512_mask_cmp_pd_mask(live, q, reach, _CMP_LE_OQ);
        const __m512d distance = _mm512_maskz_sqrt_pd(live, q);
        const __m256i bin = _mm512_maskz_cvttpd_epi32(
            live, _mm512_add_pd(_mm512_mul_pd(distance, per_width), half));
        const __mmask8 counted = _mm256_mask_cmplt_epu32_mask(near, bin, bins);
        const __m256i slot = _mm256_add_epi32(lane_start, bin);
        if (n > Slots::kCapacity || splits > Slots::kCapacity) {
            slots.n = n;
            slots.splits = splits;
            slots.flush(lanes, weight, s, split);
            n = 0;
            splits = 0;
        }
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(at + n),
                            _mm256_maskz_compress_epi32(counted, slot));
        n += static_cast<unsigned>(__builtin_popcount(counted));
        const __mmask8 in_split =
            _mm256_mask_cmple_epu32_mask(counted, _mm256_sub_epi32(bin, split_first), split_bins);
        _mm512_storeu_pd(near_split + splits, _mm512_maskz_compress_pd(in_split, distance));
        splits += static_cast<unsigned>(__builtin_popcount(in_split));
    }
    slots.n = n;
    slots.splits = splits;
}

/// count_bins_avx512 over one window, flushed.
SGMP_AVX512 void count_window_avx512(const double* xs, const double* ys, const double* zs,
                                     const double (&a)[3], std::size_t from, std::size_t to,
                                     std::int64_t weight, const BinSetup& s, std::int64_t* lanes,
                                     std::int64_t (&split)[2]) {
    Slots slots;
    count_bins_avx512(xs, ys, zs, a, from, to, weight, s, lanes, slots, split);
    slots.flush(lanes, weight, s, split);
}

SGMP_AVX512 void count_column_bins_avx512(const double* ox, const double* oy, const double* oz,
                                          std::size_t begin, std::size_t end, const double* xs,
                                          const double* ys, const double* zs, std::size_t first,
                                          std::size_t last, double half, bool own,
                                          std::int64_t weight, const BinSetup& s,
                                          std::int64_t* lanes, std::int64_t (&split)[2]) {
    Slots slots;
    std::size_t lo = first;
    std::size_t hi = first;
    for (std::size_t p = begin; p < end;) {
        const double zp = oz[p];
        lo = detail::first_not_below(zs, lo, last, zp - half);
        if (lo == last) {
            break;  // every later origin's window is empty too
        }
        hi = detail::first_above(zs, std::max(hi, lo), last, zp + half);
        if (hi == lo) {
            // An empty window (z_lo > z_p + half): so are those of the next origins up to
            // the first with z + half ≥ z_lo; their windows start at lo or later.
            p = detail::first_reaching(oz, p + 1, end, half, zs[lo]);
            continue;
        }
        const double a[3] = {ox[p], oy[p], zp};
        count_bins_avx512(xs, ys, zs, a, own ? std::max(lo, p + 1) : lo, hi, weight, s, lanes,
                          slots, split);
        ++p;
    }
    slots.flush(lanes, weight, s, split);
}

/// Pairs in the split windows, four lanes of 64-bit counts (a true comparison is all ones,
/// −1, subtracted).
struct SplitLanes {
    __m256i counts[2];
};

/// Byte shuffles that pack the 32-bit lanes of a group of four whose bit is set in the
/// index to the front, in lane order (the AVX2 stand-in for vpcompressd).
struct PackTable {
    alignas(16) std::int8_t control[16][16];

    constexpr PackTable() : control{} {
        for (int mask = 0; mask < 16; ++mask) {
            int to = 0;
            for (int lane = 0; lane < 4; ++lane) {
                if ((mask >> lane) & 1) {
                    for (int b = 0; b < 4; ++b) {
                        control[mask][4 * to + b] = static_cast<std::int8_t>(4 * lane + b);
                    }
                    ++to;
                }
            }
            for (int b = 4 * to; b < 16; ++b) {
                control[mask][b] = -1;
            }
        }
    }
};
constexpr PackTable kPackTable;

/// count_bins four candidates at a time (AVX2). A candidate not within reach (or past the
/// window's end) has its bin argument replaced by a NaN, which converts to 0x80000000 as
/// the scalar conversion does out of range, and so is not counted (b ≥ bins, unsigned).
/// The counted candidates' slots are packed into `slots` (lanes alternating between the
/// histogram's lanes 0–3 and 4–7), added in bulk by Slots::flush; split candidates are
/// counted in vector lanes.
SGMP_AVX2 inline __attribute__((always_inline)) void count_bins_avx2(
    const double* xs, const double* ys, const double* zs, const double (&a)[3], std::size_t from,
    std::size_t to, std::int64_t weight, const BinSetup& s, std::int64_t* lanes, Slots& slots,
    SplitLanes& in_split) {
    const __m256d ax = _mm256_set1_pd(a[0]);
    const __m256d ay = _mm256_set1_pd(a[1]);
    const __m256d az = _mm256_set1_pd(a[2]);
    const __m256d reach = _mm256_set1_pd(s.reach_squared);
    const __m256d per_width = _mm256_set1_pd(s.per_width);
    const __m256d half = _mm256_set1_pd(0.5);
    const __m256d nan = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    const __m128i last_bin = _mm_set1_epi32(static_cast<int>(s.bins - 1));
    const __m128i split_first = _mm_set1_epi32(static_cast<int>(s.split_first));
    const __m128i split_bins = _mm_set1_epi32(static_cast<int>(s.split_bins));
    const __m256d split_lo[2] = {_mm256_set1_pd(s.split_lo[0]), _mm256_set1_pd(s.split_lo[1])};
    const __m256d split_hi[2] = {_mm256_set1_pd(s.split_hi[0]), _mm256_set1_pd(s.split_hi[1])};
    const auto stride = static_cast<int>(s.bins + 1);
    const __m128i lane_start[2] = {
        _mm_mullo_epi32(_mm_setr_epi32(0, 1, 2, 3), _mm_set1_epi32(stride)),
        _mm_mullo_epi32(_mm_setr_epi32(4, 5, 6, 7), _mm_set1_epi32(stride))};
    std::size_t n = slots.n;  // in a register: the buffer's stores may alias any memory
    std::int32_t* const at = slots.at;
    unsigned group = 0;
    for (std::size_t k = from; k < to; k += 4, group ^= 1u) {
        const auto [q, live] = detail::squared_distances_avx2(xs, ys, zs, ax, ay, az, k, to);
        const __m256d near = _mm256_and_pd(_mm256_cmp_pd(q, reach, _CMP_LE_OQ), live);
        const __m256d distance = _mm256_sqrt_pd(q);
        const __m256d scaled = _mm256_or_pd(_mm256_add_pd(_mm256_mul_pd(distance, per_width), half),
                                            _mm256_andnot_pd(near, nan));
        const __m128i bin = _mm256_cvttpd_epi32(scaled);
        const __m128i counted = _mm_cmpeq_epi32(_mm_min_epu32(bin, last_bin), bin);
        const auto mask = static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(counted)));
        if (n > Slots::kCapacity) {
            slots.n = n;
            slots.flush_bins(lanes, weight);
            n = 0;
        }
        _mm_storeu_si128(
            reinterpret_cast<__m128i*>(at + n),
            _mm_shuffle_epi8(
                _mm_add_epi32(lane_start[group], bin),
                _mm_load_si128(reinterpret_cast<const __m128i*>(kPackTable.control[mask]))));
        n += static_cast<unsigned>(__builtin_popcount(mask));
        const __m128i offset = _mm_sub_epi32(bin, split_first);
        const __m128i near_split =
            _mm_and_si128(counted, _mm_cmpeq_epi32(_mm_min_epu32(offset, split_bins), offset));
        const __m256d candidate = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(near_split));
        for (int w = 0; w < 2; ++w) {
            const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(distance, split_lo[w], _CMP_GE_OQ),
                                                 _mm256_cmp_pd(distance, split_hi[w], _CMP_LE_OQ));
            in_split.counts[w] = _mm256_sub_epi64(
                in_split.counts[w], _mm256_castpd_si256(_mm256_and_pd(candidate, inside)));
        }
    }
    slots.n = n;
}

/// Adds the split lanes' counts, times weight, to split.
SGMP_AVX2 void add_split_lanes(const SplitLanes& in_split, std::int64_t weight,
                               std::int64_t (&split)[2]) {
    for (int w = 0; w < 2; ++w) {
        alignas(32) std::int64_t n[4];
        _mm256_store_si256(reinterpret_cast<__m256i*>(n), in_split.counts[w]);
        split[w] += weight * (((n[0] + n[1]) + n[2]) + n[3]);
    }
}

SGMP_AVX2 void count_window_avx2(const double* xs, const double* ys, const double* zs,
                                 const double (&a)[3], std::size_t from, std::size_t to,
                                 std::int64_t weight, const BinSetup& s, std::int64_t* lanes,
                                 std::int64_t (&split)[2]) {
    Slots slots;
    SplitLanes in_split{{_mm256_setzero_si256(), _mm256_setzero_si256()}};
    count_bins_avx2(xs, ys, zs, a, from, to, weight, s, lanes, slots, in_split);
    slots.flush_bins(lanes, weight);
    add_split_lanes(in_split, weight, split);
}

/// count_column_bins with count_bins_avx2 over the windows of for_each_nonempty_window.
SGMP_AVX2 void count_column_bins_avx2(const double* ox, const double* oy, const double* oz,
                                      std::size_t begin, std::size_t end, const double* xs,
                                      const double* ys, const double* zs, std::size_t first,
                                      std::size_t last, double half, bool own, std::int64_t weight,
                                      const BinSetup& s, std::int64_t* lanes,
                                      std::int64_t (&split)[2]) {
    Slots slots;
    SplitLanes in_split{{_mm256_setzero_si256(), _mm256_setzero_si256()}};
    // The walk is compiled for the default target and inlined here; the window's body
    // carries the AVX2 target itself (a lambda does not inherit its function's target).
    for_each_nonempty_window(oz, begin, end, zs, first, last, half,
                             [&](std::size_t p, std::size_t lo, std::size_t hi) SGMP_AVX2 {
                                 const double a[3] = {ox[p], oy[p], oz[p]};
                                 count_bins_avx2(xs, ys, zs, a, own ? std::max(lo, p + 1) : lo, hi,
                                                 weight, s, lanes, slots, in_split);
                             });
    slots.flush_bins(lanes, weight);
    add_split_lanes(in_split, weight, split);
}
#endif

}  // namespace

namespace detail {
bool avx512_on = cpu_avx512;
bool avx2_on = cpu_avx2;
}  // namespace detail

void enable_vector_kernels(bool on) {
    detail::avx512_on = on && cpu_avx512;
    detail::avx2_on = on && cpu_avx2;
}

void count_bins_scalar(const double* xs, const double* ys, const double* zs, const double (&a)[3],
                       std::size_t from, std::size_t to, std::int64_t weight, const BinSetup& s,
                       std::int64_t* lanes, std::int64_t (&split)[2]) {
    const std::size_t stride = s.bins + 1;
    for (std::size_t k = from; k < to; ++k) {
        const double dx = xs[k] - a[0];
        const double dy = ys[k] - a[1];
        const double dz = zs[k] - a[2];
        const double q = dx * dx + dy * dy + dz * dz;
        const double distance = std::sqrt(q);
        // bin_of's arithmetic; a 32-bit conversion gives the same value below 2³¹ bins.
        const auto b =
            static_cast<std::uint32_t>(static_cast<std::int32_t>(distance * s.per_width + 0.5));
        const bool counted = q <= s.reach_squared && b < s.bins;
        lanes[((k - from) % kBinLanes) * stride + (counted ? b : s.bins)] += weight;
        if (counted && b - s.split_first <= s.split_bins) {  // unsigned: one compare
            count_split(distance, weight, s, split);
        }
    }
}

void count_column_bins(const double* ox, const double* oy, const double* oz, std::size_t begin,
                       std::size_t end, const double* xs, const double* ys, const double* zs,
                       std::size_t first, std::size_t last, double half, bool own,
                       std::int64_t weight, const BinSetup& s, std::int64_t* lanes,
                       std::int64_t (&split)[2]) {
#if defined(SGMP_PAIR_KERNELS_AVX512)
    if (detail::avx512_on) {
        count_column_bins_avx512(ox, oy, oz, begin, end, xs, ys, zs, first, last, half, own, weight,
                                 s, lanes, split);
        return;
    }
    if (detail::avx2_on) {
        count_column_bins_avx2(ox, oy, oz, begin, end, xs, ys, zs, first, last, half, own, weight,
                               s, lanes, split);
        return;
    }
#endif
    std::size_t lo = first;
    std::size_t hi = first;
    for (std::size_t p = begin; p < end; ++p) {
        const double zp = oz[p];
        while (lo < last && zs[lo] < zp - half) {
            ++lo;
        }
        hi = std::max(hi, lo);
        while (hi < last && zs[hi] <= zp + half) {
            ++hi;
        }
        const double a[3] = {ox[p], oy[p], zp};
        count_bins_scalar(xs, ys, zs, a, own ? std::max(lo, p + 1) : lo, hi, weight, s, lanes,
                          split);
    }
}

void count_bins(const double* xs, const double* ys, const double* zs, const double (&a)[3],
                std::size_t from, std::size_t to, std::int64_t weight, const BinSetup& s,
                std::int64_t* lanes, std::int64_t (&split)[2]) {
#if defined(SGMP_PAIR_KERNELS_AVX512)
    if (detail::avx512_on) {
        count_window_avx512(xs, ys, zs, a, from, to, weight, s, lanes, split);
        return;
    }
    if (detail::avx2_on) {
        count_window_avx2(xs, ys, zs, a, from, to, weight, s, lanes, split);
        return;
    }
#endif
    count_bins_scalar(xs, ys, zs, a, from, to, weight, s, lanes, split);
}

}  // namespace sgmp::metrics
