#include "sgmp/engine/free_arcs.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

namespace sgmp::engine {

namespace {

constexpr double kPi = std::numbers::pi;

/// atan2 to ~3e-5 rad (only used to locate run ends, which are then settled exactly).
double rough_atan2(double y, double x) {
    const double ax = std::abs(x);
    const double ay = std::abs(y);
    const double big = std::max(ax, ay);
    if (big == 0.0) {
        return 0.0;
    }
    const double t = std::min(ax, ay) / big;
    const double s = t * t;
    double angle = ((-0.0464964749 * s + 0.15931422) * s - 0.327622764) * s * t + t;
    if (ay > ax)
        angle = 0.5 * kPi - angle;
    if (x < 0.0)
        angle = kPi - angle;
    return y < 0.0 ? -angle : angle;
}

/// acos to ~2e-8 rad (Abramowitz & Stegun 4.4.46).
double rough_acos(double x) {
    const double ax = std::abs(x);
    double p = -0.0012624911;
    p = p * ax + 0.0066700901;
    p = p * ax - 0.0170881256;
    p = p * ax + 0.0308918810;
    p = p * ax - 0.0501743046;
    p = p * ax + 0.0889789874;
    p = p * ax - 0.2145988016;
    p = p * ax + 1.5707963050;
    const double angle = std::sqrt(1.0 - ax) * p;
    return x >= 0.0 ? angle : kPi - angle;
}

/// Collects runs of set bits of out.bits (n samples) into out.start/length.
void runs_from_bits(int n, FreeRuns& out) {
    const auto next = [&](int from, bool value) {  // first sample ≥ from with this flag
        while (from < n) {
            const int w = from / 64;
            std::uint64_t word = value ? out.bits[w] : ~out.bits[w];
            word &= ~std::uint64_t{0} << (from % 64);
            if (word != 0) {
                return std::min(n, 64 * w + std::countr_zero(word));
            }
            from = 64 * (w + 1);
        }
        return n;
    };
    for (int k = next(0, true); k < n; k = next(k, true)) {
        const int end = next(k, false);
        out.start.push_back(k);
        out.length.push_back(end - k);
        out.free_count += end - k;
        k = end;
    }
}

enum class Run { Found, Empty, Undecided };

/// ⌈x⌉ and ⌊x⌋ as integers, exact for |x| < 2^52 (std::ceil is a library call without SSE4.1).
long ceil_to_long(double x) {
    const long i = static_cast<long>(x);  // truncates toward zero
    return i + (static_cast<double>(i) < x ? 1 : 0);
}
long floor_to_long(double x) {
    const long i = static_cast<long>(x);
    return i - (static_cast<double>(i) > x ? 1 : 0);
}

/// Sample tests of one constraint: blocked(k) for an unwrapped index k within a few turns.
struct SampleTest {
    const double* ux;
    const double* uz;
    long n;
    double a;
    double b;
    double q;
    [[nodiscard]] long wrap(long k) const {
        while (k < 0)
            k += n;  // k stays within a few turns: cheaper than %
        while (k >= n)
            k -= n;
        return k;
    }
    [[nodiscard]] bool blocked(long k) const {
        k = wrap(k);
        return a * ux[k] + b * uz[k] < q;
    }
};

/// True when the constraint is too close to tangency (or constant) for its blocked samples to
/// be trusted as one run: every sample is then tested (`free_runs_by_samples`).
/// Decided on squares, |q| ≥ (1 − 10⁻⁶)·R ⟺ q² ≥ (1 − 10⁻⁶)²·R², without a square root; the
/// margin only has to keep rounding away from the run ends, so where rounding puts the
/// boundary does not matter: both routes give the same runs.
bool near_tangency(const Blocker& c) {
    constexpr double kMargin = (1.0 - 1e-6) * (1.0 - 1e-6);
    const double radius2 = c.a * c.a + c.b * c.b;
    return radius2 == 0.0 || c.q * c.q >= kMargin * radius2;
}

/// The run of samples one constraint blocks, as unwrapped indices [lo, hi]; the constraint
/// is not near tangency (`near_tangency`).
Run blocked_run(const SweepTable& table, const Blocker& c, long& lo, long& hi) {
    const int n = table.positions();
    const SampleTest test{table.sample_x(), table.sample_z(), n, c.a, c.b, c.q};
    const auto blocked = [&](long k) { return test.blocked(k); };
    const double radius = std::sqrt(c.a * c.a + c.b * c.b);
    const double psi = rough_atan2(c.a, c.b);
    const double beta = rough_acos(c.q / radius);
    const double per_radian = n / (2.0 * kPi);
    lo = ceil_to_long((psi + beta) * per_radian);
    hi = floor_to_long((psi + 2.0 * kPi - beta) * per_radian);
    constexpr int kMaxSteps = 64;  // the estimates are off by far less than this
    int steps = 0;
    if (lo > hi || !blocked(lo) || !blocked(hi)) {
        // Shrink onto blocked samples (or find the one nearest the arc's middle).
        while (lo <= hi && !blocked(lo) && ++steps < kMaxSteps)
            ++lo;
        while (hi >= lo && !blocked(hi) && ++steps < kMaxSteps)
            --hi;
        if (lo > hi) {
            const long middle = std::lround((psi + kPi) * per_radian);
            lo = hi = middle;
            if (!blocked(middle)) {
                return blocked(middle - 1) || blocked(middle + 1) ? Run::Undecided : Run::Empty;
            }
        }
        if (steps >= kMaxSteps)
            return Run::Undecided;
    }
    // Grow to the true ends.
    while (hi - lo + 1 < n && blocked(lo - 1) && ++steps < kMaxSteps)
        --lo;
    while (hi - lo + 1 < n && blocked(hi + 1) && ++steps < kMaxSteps)
        ++hi;
    return steps >= kMaxSteps ? Run::Undecided : Run::Found;
}

/// Settles the run [lo, hi] from a guess (the run the same obstacle blocked one move
/// earlier): moves each end by at most a few samples onto the exact end, testing samples
/// only. False when the guess is too far off (or the constraint blocks every sample).
/// Away from tangency the blocked samples form one run, so an end with a blocked sample on
/// one side and a free one on the other is that run's end: the result is exact.
bool settle_guess(const SampleTest& test, long& lo, long& hi) {
    constexpr int kMaxSteps = 4;
    int steps = 0;
    while (test.blocked(lo - 1)) {
        if (++steps > kMaxSteps)
            return false;
        --lo;
    }
    while (!test.blocked(lo)) {
        if (++steps > kMaxSteps || lo >= hi)
            return false;
        ++lo;
    }
    while (test.blocked(hi + 1)) {
        if (++steps > kMaxSteps)
            return false;
        ++hi;
    }
    while (!test.blocked(hi)) {
        if (++steps > kMaxSteps || hi <= lo)
            return false;
        --hi;
    }
    return hi - lo + 1 < test.n;
}

}  // namespace

void free_runs_by_samples(const SweepTable& table, const std::vector<Blocker>& blockers,
                          FreeRuns& out) {
    // Free flags packed 64 to a word (bit k of word w: sample 64w + k), two samples at a
    // time. Sample k is free iff a·u_x + b·u_z ≥ q for every constraint.
    const int n = table.positions();
    const double* ux = table.sample_x();
    const double* uz = table.sample_z();
    const int words = (n + 63) / 64;
    out.bits.resize(static_cast<std::size_t>(words));
    for (int w = 0; w < words; ++w) {
        const int begin = 64 * w;
        const int end = std::min(n, begin + 64);
        std::uint64_t bits = 0;
        int k = begin;
#if defined(__SSE2__)
        for (; k + 1 < end; k += 2) {
            const __m128d x = _mm_loadu_pd(ux + k);
            const __m128d z = _mm_loadu_pd(uz + k);
            __m128d free = _mm_cmpeq_pd(x, x);  // all ones
            for (const Blocker& c : blockers) {
                const __m128d value =
                    _mm_add_pd(_mm_mul_pd(_mm_set1_pd(c.a), x), _mm_mul_pd(_mm_set1_pd(c.b), z));
                free = _mm_and_pd(free, _mm_cmpge_pd(value, _mm_set1_pd(c.q)));
            }
            bits |= static_cast<std::uint64_t>(_mm_movemask_pd(free)) << (k - begin);
        }
#endif
        for (; k < end; ++k) {
            bool free = true;
            for (const Blocker& c : blockers) {
                free = free && c.a * ux[k] + c.b * uz[k] >= c.q;
            }
            bits |= static_cast<std::uint64_t>(free) << (k - begin);
        }
        out.bits[w] = bits;
    }
    out.start.clear();
    out.length.clear();
    out.free_count = 0;
    runs_from_bits(n, out);
}

void free_runs(const SweepTable& table, const std::vector<Blocker>& blockers, FreeRuns& out) {
    const long n = table.positions();
    // Guesses are the runs of the previous call (the same obstacles one move earlier, in the
    // same order, as a rule); a guess is only a starting point, so a wrong one costs time only.
    const bool guesses = out.guess_positions == n;
    out.guess_positions = n;
    if (out.guess.size() < blockers.size()) {
        out.guess.resize(blockers.size(), {0, -1});
    }
    // Blocked runs, split at angle 0 into runs within [0, n), kept sorted by insertion (a
    // sweep has a few obstacles).
    out.blocked.resize(2 * blockers.size() + 1);
    std::pair<long, long>* blocked = out.blocked.data();
    std::size_t blocked_count = 0;
    const auto add_blocked = [&](long from, long to) {
        std::size_t k = blocked_count++;
        for (; k > 0 && blocked[k - 1] > std::pair<long, long>{from, to}; --k) {
            blocked[k] = blocked[k - 1];
        }
        blocked[k] = {from, to};
    };
    for (std::size_t i = 0; i < blockers.size(); ++i) {
        const Blocker& c = blockers[i];
        const SampleTest test{table.sample_x(), table.sample_z(), n, c.a, c.b, c.q};
        std::pair<long, long>& guess = out.guess[i];
        long lo = guess.first;
        long hi = guess.second;
        Run run = Run::Undecided;
        if (near_tangency(c)) {
            run = Run::Undecided;  // constant or near tangency: test every sample
        } else if (guesses && hi >= lo && settle_guess(test, lo, hi)) {
            run = Run::Found;
        } else {
            run = blocked_run(table, c, lo, hi);
        }
        if (run == Run::Undecided) {
            out.guess_positions = 0;
            free_runs_by_samples(table, blockers, out);
            return;
        }
        guess = {0, -1};
        if (run == Run::Empty) {
            continue;
        }
        if (hi - lo + 1 >= n) {
            add_blocked(0, n);
            continue;
        }
        const long start = test.wrap(lo);
        const long end = start + (hi - lo + 1);  // exclusive, may pass n
        guess = {start, end - 1};
        if (end <= n) {
            add_blocked(start, end);
        } else {
            add_blocked(start, n);
            add_blocked(0, end - n);
        }
    }
    // Free runs are the gaps between the merged blocked runs.
    out.start.clear();
    out.length.clear();
    out.free_count = 0;
    long covered = 0;  // every sample below this is blocked or already emitted
    const auto emit_free = [&](long from, long to) {
        if (to > from) {
            out.start.push_back(static_cast<int>(from));
            out.length.push_back(static_cast<int>(to - from));
            out.free_count += static_cast<int>(to - from);
        }
    };
    for (std::size_t k = 0; k < blocked_count; ++k) {
        emit_free(covered, blocked[k].first);
        covered = std::max(covered, blocked[k].second);
    }
    emit_free(covered, n);
}

}  // namespace sgmp::engine
