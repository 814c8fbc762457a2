#pragma once
/// @file pair_kernels.hpp
/// The inner loops of the pair passes over one window [from, to) of a grid's stored
/// centres (structure of arrays x, y, z) and one centre a, eight candidates at a time with
/// AVX-512 where the CPU has it, else four at a time with AVX2 where it has that (checked
/// once at run time), else one at a time.
///
/// Every version evaluates, for every candidate k, the same IEEE-754 double expressions in
/// the same order, with no contraction (-ffp-contract=off):
///     q_k = ((x_k − a_x)·(x_k − a_x) + (y_k − a_y)·(y_k − a_y)) + (z_k − a_z)·(z_k − a_z),
///     s_k = √q_k (correctly rounded),   b_k = trunc_int32(s_k·(1/ΔR) + ½),
/// so every comparison of q_k with a threshold and every bin b_k is bit for bit the one a
/// scalar loop computes: the vector lanes change only how many candidates are evaluated per
/// instruction, never a count. Candidates whose test fails are counted into a dump bin
/// (index `bins`) instead of being branched over, so the loops carry no branch on data.

#include <cstddef>
#include <cstdint>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SGMP_PAIR_KERNELS_AVX512 1
#define SGMP_AVX512 __attribute__((target("avx512f,avx512dq,avx512vl")))
// AVX2 alone (no FMA: no contraction can arise, whatever the flags).
#define SGMP_AVX2 __attribute__((target("avx2")))
#endif

namespace sgmp::metrics {

namespace detail {
extern bool avx512_on;  ///< set at start-up from the CPU's features
extern bool avx2_on;    ///< set at start-up: the CPU has AVX2 but not AVX-512
}  // namespace detail

/// True when the vector kernels are in use: the CPU has AVX-512 (F, DQ, VL) or AVX2 and
/// they are not switched off.
inline bool vector_kernels() {
    return detail::avx512_on || detail::avx2_on;
}
/// Switches the vector kernels off (false) or back on where the CPU has them (true); for
/// tests that compare them with the scalar loops. Not thread-safe against running passes.
void enable_vector_kernels(bool on);

/// Histogram lanes of count_bins: candidate k of each group of eight counts into lane
/// k mod 8, so consecutive increments of one bin (neighbours met in a column lie at
/// similar distances) do not wait on each other's stores. Integer counts: the split into
/// lanes never changes a total.
inline constexpr std::size_t kBinLanes = 8;

/// What count_bins needs of the g(r) pass: reach² (pairs beyond it are not counted), 1/ΔR,
/// the number of bins, and the split-ratio windows [lo_w, hi_w] (distances, w = 0, 1) with
/// the bins [split_first, split_first + split_bins] that can hold one of their distances
/// (the exact test on the distance decides).
struct BinSetup {
    double reach_squared;
    double per_width;
    std::uint32_t bins;
    std::uint32_t split_first;
    std::uint32_t split_bins;
    double split_lo[2];
    double split_hi[2];
};

/// Adds `weight` to lanes[(k mod kBinLanes)·(bins + 1) + b_k] for every candidate k in
/// [from, to) with q_k ≤ reach² and b_k < bins (others to the dump bin b = bins), and
/// weight to split[w] for each such k with lo_w ≤ s_k ≤ hi_w. `lanes` holds
/// kBinLanes·(bins + 1) counters.
void count_bins(const double* xs, const double* ys, const double* zs, const double (&a)[3],
                std::size_t from, std::size_t to, std::int64_t weight, const BinSetup& s,
                std::int64_t* lanes, std::int64_t (&split)[2]);
/// The same one candidate at a time (the fallback, and the tests' reference).
void count_bins_scalar(const double* xs, const double* ys, const double* zs, const double (&a)[3],
                       std::size_t from, std::size_t to, std::int64_t weight, const BinSetup& s,
                       std::int64_t* lanes, std::int64_t (&split)[2]);

/// count_bins over the sliding windows of one pair of columns (PairColumns::for_each_column):
/// for each origin p in [begin, end) of the arrays (ox, oy, oz), z increasing, the
/// candidates [lo_p, hi_p) of the column [first, last) of (xs, ys, zs), z increasing, with
/// lo_p the first position with z ≥ z_p − half and hi_p the first after it with
/// z > z_p + half; with `own` (the same column of the same arrays) only those after p.
void count_column_bins(const double* ox, const double* oy, const double* oz, std::size_t begin,
                       std::size_t end, const double* xs, const double* ys, const double* zs,
                       std::size_t first, std::size_t last, double half, bool own,
                       std::int64_t weight, const BinSetup& s, std::int64_t* lanes,
                       std::int64_t (&split)[2]);

/// The sliding windows of one pair of columns (PairColumns::for_each_column) for the origins
/// [begin, end) of `oz` (z increasing) over the column [first, last) of `zs` (z increasing), the
/// empty ones left out: f(p, lo, hi) with lo the first position with z ≥ z_p − half, hi the first
/// after it with z > z_p + half, only where lo < hi. An empty window (z_lo > z_p + half) skips at
/// once to the first origin with z + half ≥ z_lo: the windows of those between are empty too.
template <class F>
void for_each_nonempty_window(const double* oz, std::size_t begin, std::size_t end,
                              const double* zs, std::size_t first, std::size_t last, double half,
                              F&& f) {
    std::size_t lo = first;
    std::size_t hi = first;
    for (std::size_t p = begin; p < end;) {
        const double zp = oz[p];
        while (lo < last && zs[lo] < zp - half) {
            ++lo;
        }
        if (lo == last) {
            return;
        }
        hi = hi > lo ? hi : lo;
        while (hi < last && zs[hi] <= zp + half) {
            ++hi;
        }
        if (hi == lo) {
            const double target = zs[lo];
            ++p;
            while (p < end && oz[p] + half < target) {
                ++p;
            }
            continue;
        }
        f(p, lo, hi);
        ++p;
    }
}

namespace detail {
/// Calls f(k, q_k) for every k in [from, to) with q_k ≤ limit, in increasing k.
template <class F>
void for_each_within_scalar(const double* xs, const double* ys, const double* zs,
                            const double (&a)[3], std::size_t from, std::size_t to, double limit,
                            F&& f) {
    for (std::size_t k = from; k < to; ++k) {
        const double dx = xs[k] - a[0];
        const double dy = ys[k] - a[1];
        const double dz = zs[k] - a[2];
        const double q = dx * dx + dy * dy + dz * dz;
        if (q <= limit) {
            f(k, q);
        }
    }
}

#if defined(SGMP_PAIR_KERNELS_AVX512)
/// The first position p in [at, end) with not (z_p + offset `Cmp` t), eight at a time (z
/// increasing: the positions where it holds are a prefix). Adding an offset of 0 changes no
/// comparison.
template <int Cmp>
SGMP_AVX512 inline std::size_t first_not(const double* z, std::size_t at, std::size_t end,
                                         double offset, double t) {
    const __m512d bound = _mm512_set1_pd(t);
    const __m512d shift = _mm512_set1_pd(offset);
    while (at < end) {
        const std::size_t n = end - at;
        const __mmask8 live = n >= 8 ? __mmask8(0xff) : __mmask8((1u << n) - 1u);
        const unsigned holds = _mm512_mask_cmp_pd_mask(
            live, _mm512_add_pd(_mm512_maskz_loadu_pd(live, z + at), shift), bound, Cmp);
        if (holds != 0xffu) {
            return at + static_cast<unsigned>(__builtin_ctz(~holds));
        }
        at += 8;
    }
    return at;
}

/// The first position in [at, last) whose z is not below t.
SGMP_AVX512 inline std::size_t first_not_below(const double* z, std::size_t at, std::size_t last,
                                               double t) {
    return first_not<_CMP_LT_OQ>(z, at, last, 0.0, t);
}

/// The first position in [at, last) whose z is above t.
SGMP_AVX512 inline std::size_t first_above(const double* z, std::size_t at, std::size_t last,
                                           double t) {
    return first_not<_CMP_LE_OQ>(z, at, last, 0.0, t);
}

/// The first position p in [at, end) with z_p + half ≥ t (z increasing).
SGMP_AVX512 inline std::size_t first_reaching(const double* z, std::size_t at, std::size_t end,
                                              double half, double t) {
    return first_not<_CMP_LT_OQ>(z, at, end, half, t);
}

template <class F>
SGMP_AVX512 void for_each_within_avx512(const double* xs, const double* ys, const double* zs,
                                        const double (&a)[3], std::size_t from, std::size_t to,
                                        double limit, F&& f) {
    const __m512d ax = _mm512_set1_pd(a[0]);
    const __m512d ay = _mm512_set1_pd(a[1]);
    const __m512d az = _mm512_set1_pd(a[2]);
    const __m512d bound = _mm512_set1_pd(limit);
    alignas(64) double qs[8];
    for (std::size_t k = from; k < to; k += 8) {
        const std::size_t n = to - k;
        const __mmask8 live = n >= 8 ? __mmask8(0xff) : __mmask8((1u << n) - 1u);
        const __m512d dx = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, xs + k), ax);
        const __m512d dy = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, ys + k), ay);
        const __m512d dz = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, zs + k), az);
        const __m512d q = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)),
                                        _mm512_mul_pd(dz, dz));
        unsigned hits = _mm512_mask_cmp_pd_mask(live, q, bound, _CMP_LE_OQ);
        if (hits == 0) {
            continue;
        }
        _mm512_store_pd(qs, q);
        while (hits != 0) {
            const unsigned j = static_cast<unsigned>(__builtin_ctz(hits));
            hits &= hits - 1;
            f(k + j, qs[j]);
        }
    }
}

/// for_each_pair_within on the CPU's vectors: the same windows and pairs, in the same order.
template <class F>
SGMP_AVX512 void for_each_pair_within_avx512(const double* ox, const double* oy, const double* oz,
                                             std::size_t begin, std::size_t end, const double* xs,
                                             const double* ys, const double* zs, std::size_t first,
                                             std::size_t last, double half, bool after,
                                             double limit, F&& f) {
    std::size_t lo = first;
    std::size_t hi = first;
    for (std::size_t p = begin; p < end;) {
        const double zp = oz[p];
        lo = first_not_below(zs, lo, last, zp - half);
        if (lo == last) {
            return;
        }
        hi = first_above(zs, hi > lo ? hi : lo, last, zp + half);
        if (hi == lo) {
            p = first_reaching(oz, p + 1, end, half, zs[lo]);
            continue;
        }
        const double a[3] = {ox[p], oy[p], zp};
        const std::size_t from = after && lo <= p ? p + 1 : lo;
        for_each_within_avx512(xs, ys, zs, a, from, hi, limit,
                               [&](std::size_t k, double q) { f(p, k, q); });
        ++p;
    }
}

/// Squared distances from (ax, ay, az) to the candidates k…k+3 of (xs, ys, zs), as
/// for_each_within_scalar computes them; lanes at or past `to` are loaded as zeros and
/// `live` is all ones in the lanes before `to`, zero after.
struct FourDistances {
    __m256d q;
    __m256d live;
};
SGMP_AVX2 inline __attribute__((always_inline)) FourDistances squared_distances_avx2(
    const double* xs, const double* ys, const double* zs, __m256d ax, __m256d ay, __m256d az,
    std::size_t k, std::size_t to) {
    __m256d x, y, z;
    __m256i mask = _mm256_set1_epi64x(-1);
    if (to - k >= 4) {
        x = _mm256_loadu_pd(xs + k);
        y = _mm256_loadu_pd(ys + k);
        z = _mm256_loadu_pd(zs + k);
    } else {
        mask = _mm256_cmpgt_epi64(_mm256_set1_epi64x(static_cast<long long>(to - k)),
                                  _mm256_setr_epi64x(0, 1, 2, 3));
        x = _mm256_maskload_pd(xs + k, mask);
        y = _mm256_maskload_pd(ys + k, mask);
        z = _mm256_maskload_pd(zs + k, mask);
    }
    const __m256d dx = _mm256_sub_pd(x, ax);
    const __m256d dy = _mm256_sub_pd(y, ay);
    const __m256d dz = _mm256_sub_pd(z, az);
    const __m256d q = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
                                    _mm256_mul_pd(dz, dz));
    return {q, _mm256_castsi256_pd(mask)};
}

/// for_each_within_scalar four candidates at a time (AVX2): the same calls, in the same order.
template <class F>
SGMP_AVX2 void for_each_within_avx2(const double* xs, const double* ys, const double* zs,
                                    const double (&a)[3], std::size_t from, std::size_t to,
                                    double limit, F&& f) {
    const __m256d ax = _mm256_set1_pd(a[0]);
    const __m256d ay = _mm256_set1_pd(a[1]);
    const __m256d az = _mm256_set1_pd(a[2]);
    const __m256d bound = _mm256_set1_pd(limit);
    alignas(32) double qs[4];
    for (std::size_t k = from; k < to; k += 4) {
        const FourDistances four = squared_distances_avx2(xs, ys, zs, ax, ay, az, k, to);
        unsigned hits = static_cast<unsigned>(
            _mm256_movemask_pd(_mm256_and_pd(_mm256_cmp_pd(four.q, bound, _CMP_LE_OQ), four.live)));
        if (hits == 0) {
            continue;
        }
        _mm256_store_pd(qs, four.q);
        while (hits != 0) {
            const unsigned j = static_cast<unsigned>(__builtin_ctz(hits));
            hits &= hits - 1;
            f(k + j, qs[j]);
        }
    }
}
#endif
}  // namespace detail

/// Every pair of an origin p in [begin, end) of (ox, oy, oz) and a centre k of the column
/// [first, last) of (xs, ys, zs) in p's window (for_each_nonempty_window) with q_pk ≤ limit:
/// f(p, k, q_pk), by increasing p, then k. With `after` (the same column of the same arrays)
/// only k > p.
template <class F>
void for_each_pair_within(const double* ox, const double* oy, const double* oz, std::size_t begin,
                          std::size_t end, const double* xs, const double* ys, const double* zs,
                          std::size_t first, std::size_t last, double half, bool after,
                          double limit, F&& f) {
#if defined(SGMP_PAIR_KERNELS_AVX512)
    if (detail::avx512_on) {
        detail::for_each_pair_within_avx512(ox, oy, oz, begin, end, xs, ys, zs, first, last, half,
                                            after, limit, f);
        return;
    }
    if (detail::avx2_on) {
        for_each_nonempty_window(oz, begin, end, zs, first, last, half,
                                 [&](std::size_t p, std::size_t lo, std::size_t hi) {
                                     const double a[3] = {ox[p], oy[p], oz[p]};
                                     const std::size_t from = after && lo <= p ? p + 1 : lo;
                                     detail::for_each_within_avx2(
                                         xs, ys, zs, a, from, hi, limit,
                                         [&](std::size_t k, double q) { f(p, k, q); });
                                 });
        return;
    }
#endif
    for_each_nonempty_window(
        oz, begin, end, zs, first, last, half, [&](std::size_t p, std::size_t lo, std::size_t hi) {
            const double a[3] = {ox[p], oy[p], oz[p]};
            const std::size_t from = after && lo <= p ? p + 1 : lo;
            detail::for_each_within_scalar(xs, ys, zs, a, from, hi, limit,
                                           [&](std::size_t k, double q) { f(p, k, q); });
        });
}

/// Calls f(k, q_k) for every k in [from, to) with q_k ≤ limit, in increasing k (a short
/// reach: few candidates pass, so the vector test leaves few calls).
template <class F>
void for_each_within(const double* xs, const double* ys, const double* zs, const double (&a)[3],
                     std::size_t from, std::size_t to, double limit, F&& f) {
#if defined(SGMP_PAIR_KERNELS_AVX512)
    if (detail::avx512_on && to >= from + 8) {  // shorter windows: the scalar loop is faster
        detail::for_each_within_avx512(xs, ys, zs, a, from, to, limit, f);
        return;
    }
    if (detail::avx2_on && to >= from + 4) {
        detail::for_each_within_avx2(xs, ys, zs, a, from, to, limit, f);
        return;
    }
#endif
    detail::for_each_within_scalar(xs, ys, zs, a, from, to, limit, f);
}

}  // namespace sgmp::metrics
