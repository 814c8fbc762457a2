// The L2 equivalence test of g(r) (equivalence.hpp, test_l2_curves): its numbers against an
// independent numpy/scipy computation, and its two error rates at ‖Δ‖ = m against a Monte Carlo
// with fixed seeds on the per-bin variances measured on the stored DEM pours.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "sgmp/report/equivalence.hpp"

using namespace sgmp::report;

namespace {

using Curves = std::vector<std::vector<double>>;

// Relative agreement with numpy/scipy: both sides find the bounds to ~1e-15 relative (bisection
// here, brentq there) from sums that agree to rounding; the normal quantile and cdf of boost
// and scipy agree to ~1e-15. 1e-9 leaves room for the roots' conditioning, nothing more.
bool close(double a, double b, double rel = 1e-9) {
    return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b));
}

const Curves kCandidate{{1.00, 1.30, 0.80, 1.10, 0.95, 1.02}, {1.10, 1.20, 0.90, 1.00, 1.05, 0.98}};
const Curves kReference{{1.05, 1.22, 0.86, 1.02, 1.00, 1.01},
                        {0.98, 1.30, 0.82, 1.08, 0.97, 0.99},
                        {1.02, 1.18, 0.88, 1.06, 1.03, 1.00},
                        {1.07, 1.26, 0.84, 0.99, 0.99, 1.03},
                        {1.00, 1.24, 0.85, 1.05, 1.01, 0.97}};

// The per-pack variance s_k² of g(r) on the judged bins (r = 1.10, 1.12, …, 5.00 d), in units of
// 1e-4: the pooled within-class variance of the stored DEM pours at N = 1002 (main μ = 0, 0.01,
// 0.5 and the truth set, 12 degrees of freedom a bin). The largest, 0.035 at r = 1.74 d, is 9×
// the mean.
const std::vector<int> kVariance1002{
    173, 137, 70, 87, 93, 84, 65, 36, 34, 41, 87,  137, 84, 40,  42, 55, 68, 52, 45, 44, 13,  72,
    29,  35,  71, 32, 46, 30, 37, 39, 47, 63, 350, 114, 58, 132, 83, 75, 63, 81, 90, 78, 125, 22,
    60,  114, 20, 41, 47, 58, 23, 23, 30, 25, 41,  36,  41, 24,  21, 28, 41, 16, 41, 20, 23,  34,
    29,  47,  50, 33, 33, 21, 49, 24, 26, 25, 27,  70,  69, 46,  54, 82, 78, 59, 22, 25, 45,  37,
    62,  21,  41, 43, 21, 20, 35, 20, 30, 18, 33,  16,  17, 38,  22, 15, 15, 20, 24, 19, 12,  13,
    7,   40,  42, 13, 16, 24, 26, 17, 38, 32, 34,  53,  32, 18,  14, 42, 27, 22, 16, 13, 13,  29,
    27,  21,  34, 15, 24, 30, 21, 21, 20, 18, 35,  20,  41, 10,  26, 23, 31, 15, 11, 27, 23,  26,
    23,  24,  23, 12, 19, 19, 18, 18, 34, 29, 22,  19,  18, 14,  29, 13, 17, 21, 18, 17, 20,  6,
    5,   9,   24, 11, 30, 3,  11, 13, 20, 27, 16,  18,  15, 21,  25, 21, 16, 19, 26, 25};

}  // namespace

BOOST_AUTO_TEST_SUITE(l2_equivalence)

// numpy/scipy (scipy 1.10.1, numpy 1.24.2), written from the header's formulas alone: sample
// variances per bin, U, the variance and third-cumulant bounds, the bounds by brentq on a grid of
// 20000 points, p-values by solving the Cornish–Fisher relation with brentq.
BOOST_AUTO_TEST_CASE(the_l2_test_matches_an_independent_numpy_computation) {
    const auto r = test_l2_curves(kCandidate, kReference, 0.1, 0.05);
    BOOST_TEST(close(r.estimate, 0.009359487165438081));
    BOOST_TEST(r.ci_low == 0.0);
    BOOST_TEST(close(r.ci_high, 0.04345287214113263));
    BOOST_TEST(close(r.p_agree, 0.04057121778927205));
    BOOST_TEST(close(r.p_differ, 0.9991741029664671));
    BOOST_TEST(close(r.mdd, 0.10102608340941918));
    BOOST_TEST(close(r.zero_bound, 0.06938780011763764));
    BOOST_TEST(close(r.standard_error, 0.02193705230882219));
    BOOST_TEST(close(r.degrees_of_freedom, 18.93422689510976));
    // U = D̂² − t̂ = −0.001324 lies far enough below the noise level: agree, though an estimate of
    // exactly 0 would not (zero_bound > m).
    BOOST_TEST(static_cast<int>(r.decision) == static_cast<int>(Decision::Agree));

    // One candidate pack takes the reference's variance.
    const auto one = test_l2_curves({kCandidate[0]}, kReference, 0.1, 0.05);
    BOOST_TEST(close(one.estimate, 0.03629876030941003));
    BOOST_TEST(one.ci_low == 0.0);
    BOOST_TEST(close(one.ci_high, 0.06991468600759586));
    BOOST_TEST(close(one.p_agree, 0.15784941644200157));
    BOOST_TEST(close(one.p_differ, 0.8425478933293145));
    BOOST_TEST(close(one.mdd, 0.09570175444712413));
    BOOST_TEST(close(one.zero_bound, 0.06183061122730333));
    BOOST_TEST(close(one.degrees_of_freedom, 27.445541614076753));
    BOOST_TEST(static_cast<int>(one.decision) == static_cast<int>(Decision::Inconclusive));
    BOOST_TEST(one.seeds_to_decide.has_value());

    // The candidate shifted by 0.4 in every bin: ‖Δ‖ ≈ 0.31.
    Curves far = kCandidate;
    for (auto& c : far) {
        for (double& g : c) {
            g += 0.4;
        }
    }
    const auto d = test_l2_curves(far, kReference, 0.1, 0.05);
    BOOST_TEST(close(d.estimate, 0.31586009561196554));
    BOOST_TEST(close(d.ci_low, 0.28104034440282816));
    BOOST_TEST(close(d.ci_high, 0.34857657582848456));
    // A tail probability of 2e-43 is computed through the normal's complement on both sides;
    // 1e-6 relative allows for its steepness in x (d ln p / dx ≈ 14 at x ≈ 14).
    BOOST_TEST(close(d.p_differ, 2.1679715576906863e-43, 1e-6));
    BOOST_TEST(static_cast<int>(d.decision) == static_cast<int>(Decision::Differ));
    // Mirrored, the same numbers.
    const auto mirrored = test_l2_curves(kReference, far, 0.1, 0.05);
    BOOST_TEST(static_cast<int>(mirrored.decision) == static_cast<int>(Decision::Differ));
}

BOOST_AUTO_TEST_CASE(too_few_curves_give_an_infinite_interval) {
    const auto r = test_l2_curves({kCandidate[0]}, {kReference[0]}, 0.1, 0.05);
    BOOST_TEST(std::isinf(r.ci_high));
    BOOST_TEST(std::isinf(r.zero_bound));
    BOOST_TEST(static_cast<int>(r.decision) == static_cast<int>(Decision::Inconclusive));
}

BOOST_AUTO_TEST_CASE(quiet_curves_decide_and_an_open_case_says_how_many_seeds_would) {
    std::mt19937_64 rng(11);
    std::normal_distribution<double> unit(0.0, 1.0);
    const auto group = [&](std::size_t n, double shift, double sd) {
        Curves c(n, std::vector<double>(100, 1.0));
        for (auto& curve : c) {
            for (double& g : curve) {
                g += shift + sd * unit(rng);
            }
        }
        return c;
    };
    // 100 bins of width 0.02: a shift s is ‖Δ‖ = s·√2.
    const auto agree = test_l2_curves(group(5, 0.0, 0.002), group(5, 0.0, 0.002), 0.02, 0.03);
    BOOST_TEST(static_cast<int>(agree.decision) == static_cast<int>(Decision::Agree));
    BOOST_TEST(agree.ci_high < 0.03);
    const auto differ = test_l2_curves(group(5, 0.1, 0.002), group(5, 0.0, 0.002), 0.02, 0.03);
    BOOST_TEST(static_cast<int>(differ.decision) == static_cast<int>(Decision::Differ));
    BOOST_TEST(differ.ci_low > 0.03);
    BOOST_TEST(differ.ci_low < differ.estimate);
    BOOST_TEST(differ.ci_high > differ.estimate);
    const auto open = test_l2_curves(group(2, 0.0, 0.05), group(5, 0.0, 0.05), 0.02, 0.03);
    BOOST_TEST(static_cast<int>(open.decision) == static_cast<int>(Decision::Inconclusive));
    BOOST_TEST(open.mdd > 0.03);
    BOOST_TEST(open.zero_bound > 0.03);
    BOOST_REQUIRE(open.seeds_to_decide.has_value());
    BOOST_TEST(*open.seeds_to_decide > 2u);
}

// The size of both one-sided tests at ‖Δ‖ = m, on the measured variances of g(r) at N = 1002 and
// a third of them (the N ≈ 3000 regime, where the linear term matters most), for the designs of
// the truth test (2 candidate packs against 5) and of the held-out seed (1 against 4), with
// independent bins and with an AR(1) correlation ρ = 0.2 between neighbours (4–10× the measured
// |ρ₁| ≤ 0.03 … 0.05), and for four directions of Δ: all of ‖Δ‖ in the bin of largest variance
// (the worst case of the linear term), in the 5 bins around it, flat, and a damped oscillation.
// 4000 trials a case: the binomial sd of a 5 % rate is 0.34 %, so 6 % is 3 sd above the level.
BOOST_AUTO_TEST_CASE(false_agree_and_false_differ_stay_below_five_percent_at_the_margin) {
    const double w = 0.02;
    const double m = 0.03;
    const std::size_t bins = kVariance1002.size();
    const std::size_t peak = static_cast<std::size_t>(
        std::max_element(kVariance1002.begin(), kVariance1002.end()) - kVariance1002.begin());
    const auto scaled = [&](std::vector<double> d) {
        double s = 0.0;
        for (const double x : d) {
            s += w * x * x;
        }
        for (double& x : d) {
            x *= m / std::sqrt(s);
        }
        return d;
    };
    std::vector<std::pair<std::string, std::vector<double>>> directions;
    std::vector<double> d(bins, 0.0);
    d[peak] = 1.0;
    directions.emplace_back("spike", scaled(d));
    for (std::size_t k = peak - 2; k <= peak + 2; ++k) {
        d[k] = 1.0;
    }
    directions.emplace_back("block", scaled(d));
    directions.emplace_back("flat", scaled(std::vector<double>(bins, 1.0)));
    for (std::size_t k = 0; k < bins; ++k) {
        const double r = 1.1 + w * static_cast<double>(k);
        d[k] = std::cos(2.0 * std::numbers::pi * r) * std::exp(-(r - 1.0));
    }
    directions.emplace_back("oscillation", scaled(d));

    const int trials = 4000;
    const double tolerance = 0.06;
    std::mt19937_64 rng(20261205);
    std::normal_distribution<double> unit(0.0, 1.0);
    double worst_agree = 0.0;
    double worst_differ = 0.0;
    for (const double scale : {1.0, 1.0 / 3.0}) {
        std::vector<double> sd(bins);
        for (std::size_t k = 0; k < bins; ++k) {
            sd[k] = std::sqrt(1e-4 * kVariance1002[k] * scale);
        }
        for (const double rho : {0.0, 0.2}) {
            const auto pack = [&](const std::vector<double>& mean) {
                std::vector<double> g(bins);
                double e = unit(rng);
                for (std::size_t k = 0; k < bins; ++k) {
                    e = k == 0 ? e : rho * e + std::sqrt(1.0 - rho * rho) * unit(rng);
                    g[k] = mean[k] + sd[k] * e;
                }
                return g;
            };
            const std::vector<double> zero(bins, 0.0);
            for (const auto& [n_a, n_b] : {std::pair{2, 5}, std::pair{1, 4}}) {
                for (const auto& [name, delta] : directions) {
                    int agree = 0;
                    int differ = 0;
                    for (int t = 0; t < trials; ++t) {
                        Curves a;
                        Curves b;
                        for (int i = 0; i < n_a; ++i) {
                            a.push_back(pack(delta));
                        }
                        for (int i = 0; i < n_b; ++i) {
                            b.push_back(pack(zero));
                        }
                        const auto r = test_l2_curves(a, b, w, m);
                        agree += r.decision == Decision::Agree ? 1 : 0;
                        differ += r.decision == Decision::Differ ? 1 : 0;
                    }
                    const double pa = static_cast<double>(agree) / trials;
                    const double pd = static_cast<double>(differ) / trials;
                    worst_agree = std::max(worst_agree, pa);
                    worst_differ = std::max(worst_differ, pd);
                    BOOST_TEST_MESSAGE("variance ×" << scale << " ρ = " << rho << " " << n_a
                                                    << " vs " << n_b << " " << name << ": agree "
                                                    << pa << ", differ " << pd);
                    BOOST_TEST(pa < tolerance, name << " " << n_a << "v" << n_b << " ρ " << rho);
                    BOOST_TEST(pd < tolerance, name << " " << n_a << "v" << n_b << " ρ " << rho);
                }
            }
        }
    }
    BOOST_TEST_MESSAGE("largest false agree " << worst_agree << ", false differ " << worst_differ);
}

BOOST_AUTO_TEST_SUITE_END()
