#pragma once
// What equivalence.cpp and l2_equivalence.cpp share (private to the library).
#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>

#include "sgmp/report/equivalence.hpp"

namespace sgmp::report::detail {

/// The power of mdd: the true difference called `differ` with this probability.
inline constexpr double kPowerQuantile = 0.80;
/// The most seeds a side seeds_to_decide names.
inline constexpr std::size_t kMostSeeds = 1000;

/// The smallest n a side that seeds_to_decide may name: never fewer seeds than either
/// group already has (a smaller set can look decisive only through the pooled sd's
/// weights), and more than both when they are equal.
inline std::size_t first_seeds_to_try(std::size_t n_a, std::size_t n_b) {
    return std::max<std::size_t>(2, std::max(n_a, n_b) + (n_a == n_b ? 1 : 0));
}

/// The smallest n in [lo, hi] with decides(n), by bisection, assuming that once it decides
/// it keeps deciding (an interval narrows as n grows); none when lo > hi or decides(hi) is
/// false. What seeds_to_decide, the L2 test and the sequential rows' projections name.
template <class F>
std::optional<std::size_t> smallest_deciding(std::size_t lo, std::size_t hi, const F& decides) {
    if (lo > hi || !decides(hi)) {
        return std::nullopt;
    }
    while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (decides(mid)) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    return lo;
}

inline EquivalenceResult undecidable(double estimate, double margin) {
    EquivalenceResult r;
    r.estimate = estimate;
    r.margin = margin;
    r.ci_low = -std::numeric_limits<double>::infinity();
    r.ci_high = std::numeric_limits<double>::infinity();
    r.standard_error = std::numeric_limits<double>::infinity();
    r.mdd = std::numeric_limits<double>::infinity();
    r.zero_bound = std::numeric_limits<double>::infinity();
    return r;
}

}  // namespace sgmp::report::detail
