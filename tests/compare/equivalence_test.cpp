// The equivalence test behind every verdict (equivalence.hpp), against values computed
// independently with scipy.stats (pooled Student t, two one-sided tests; scipy 1.10.1) and, for the
// curve tests, against Monte Carlo runs with fixed seeds (the L2 test of g(r): l2_test.cpp).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sgmp/report/equivalence.hpp"

using namespace sgmp::report;

namespace {

// Relative agreement with scipy: boost's t quantile at a few degrees of freedom is found
// by iteration and agrees with scipy's to ~1e-9 relative (measured 5e-9 on the intervals
// below), so 1e-7 leaves room only for that.
bool close(double a, double b, double rel = 1e-7) {
    return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(equivalence)

BOOST_AUTO_TEST_CASE(pooled_tost_matches_scipy_for_an_agreeing_candidate) {
    const auto r = test_scalar({0.590, 0.002, 3}, {0.585, 0.003, 5}, 0.01);
    BOOST_TEST(close(r.standard_error, 0.0019776529298921766));
    BOOST_TEST(r.degrees_of_freedom == 6.0);
    BOOST_TEST(close(r.ci_low, 0.0011570638251725187));
    BOOST_TEST(close(r.ci_high, 0.00884293617482749));
    BOOST_TEST(close(r.p_agree, 0.022392698826888238, 1e-7));
    BOOST_TEST(close(r.p_differ, 0.9776073011731118, 1e-7));
    BOOST_TEST(close(r.mdd, 0.01563410293037621));
    BOOST_TEST(static_cast<int>(r.decision) == static_cast<int>(Decision::Agree));
}

BOOST_AUTO_TEST_CASE(a_single_pack_borrows_the_reference_sd) {
    const auto r = test_scalar({0.600, 0.0, 1}, {0.585, 0.003, 5}, 0.01);
    BOOST_TEST(close(r.standard_error, 0.003286335345030997));
    BOOST_TEST(r.degrees_of_freedom == 4.0);
    BOOST_TEST(close(r.ci_low, 0.007994036572303997));
    BOOST_TEST(close(r.ci_high, 0.022005963427696028));
    BOOST_TEST(close(r.p_differ, 0.10139771557235876, 1e-7));
    BOOST_TEST(static_cast<int>(r.decision) == static_cast<int>(Decision::Inconclusive));
    BOOST_TEST(r.seeds_to_decide.has_value());
}

BOOST_AUTO_TEST_CASE(a_difference_beyond_the_margin_differs) {
    const auto r = test_scalar({0.640, 0.004, 2}, {0.585, 0.003, 5}, 0.01);
    BOOST_TEST(r.degrees_of_freedom == 5.0);
    BOOST_TEST(close(r.ci_low, 0.04956310224542057));
    BOOST_TEST(close(r.p_differ, 7.078728288553146e-06, 1e-6));
    BOOST_TEST(close(r.mdd, 0.017917962517993595));
    BOOST_TEST(static_cast<int>(r.decision) == static_cast<int>(Decision::Differ));
    // Mirrored, it differs just the same.
    const auto m = test_scalar({0.585, 0.003, 5}, {0.640, 0.004, 2}, 0.01);
    BOOST_TEST(static_cast<int>(m.decision) == static_cast<int>(Decision::Differ));
}

BOOST_AUTO_TEST_CASE(an_inconclusive_result_says_how_many_seeds_would_decide_it) {
    const auto r = test_scalar({5.9, 0.2, 2}, {5.75, 0.1, 5}, 0.3);
    BOOST_TEST(close(r.ci_low, -0.06325267495391934));
    BOOST_TEST(close(r.ci_high, 0.36325267495392005));
    BOOST_TEST(static_cast<int>(r.decision) == static_cast<int>(Decision::Inconclusive));
    // scipy: the smallest n a side with t.95(2n − 2)·SE_n < |0.15 − 0.3| is 8.
    BOOST_REQUIRE(r.seeds_to_decide.has_value());
    BOOST_TEST(*r.seeds_to_decide == 8u);
    // 2 candidates of no scatter against 5 references: 3 a side would pool the sds
    // half-and-half and look decisive; the count named is never below the 5 there are
    // (scipy: 5 a side, t.95(8)·SE = 0.0083 < 0.015).
    const auto few = test_scalar({0.015, 0.0, 2}, {0.0, 0.01, 5}, 0.03);
    BOOST_TEST(static_cast<int>(few.decision) == static_cast<int>(Decision::Inconclusive));
    BOOST_REQUIRE(few.seeds_to_decide.has_value());
    BOOST_TEST(*few.seeds_to_decide == 5u);
}

BOOST_AUTO_TEST_CASE(too_few_packs_give_an_infinite_interval) {
    const auto r = test_scalar({0.6, 0.0, 1}, {0.6, 0.0, 1}, 0.01);
    BOOST_TEST(std::isinf(r.ci_high));
    BOOST_TEST(static_cast<int>(r.decision) == static_cast<int>(Decision::Inconclusive));
}

// Over many seeds with the true difference exactly at the margin, the test calls `agree` and
// `differ` each at most α of the time (the two one-sided errors of TOST); with a true
// difference of 0, `differ` needs |Δ̂| > m + t·SE ≈ 3.3 SE here: rarer than 1 %.
BOOST_AUTO_TEST_CASE(the_test_keeps_its_level_over_many_seeds) {
    std::mt19937_64 rng(20261203);
    const double sd = 1.0;
    const double margin = 1.0;
    for (const double truth : {margin, 0.0}) {
        std::normal_distribution<double> a(truth, sd);
        std::normal_distribution<double> b(0.0, sd);
        int agree = 0;
        int differ = 0;
        const int trials = 4000;
        for (int t = 0; t < trials; ++t) {
            std::vector<double> xa(3);
            std::vector<double> xb(5);
            std::generate(xa.begin(), xa.end(), [&] { return a(rng); });
            std::generate(xb.begin(), xb.end(), [&] { return b(rng); });
            const auto r = test_scalar(sample_of(xa), sample_of(xb), margin);
            agree += r.decision == Decision::Agree ? 1 : 0;
            differ += r.decision == Decision::Differ ? 1 : 0;
        }
        // Binomial sd of a 5 % rate over 4000 trials is 0.34 %; 6.5 % is 4 sd above.
        if (truth == margin) {
            BOOST_TEST(agree < 0.065 * trials);
            BOOST_TEST(differ < 0.065 * trials);
        } else {
            BOOST_TEST(differ < 0.01 * trials);
        }
    }
}

// The total-variation noise norm ½Σ|ε_k| (normal approximation), ε_k ~ N(0, v_k), against a
// Monte Carlo: within 3 % (the approximation's error for 20 unequal bins is ~1 %).
BOOST_AUTO_TEST_CASE(the_total_variation_noise_quantile_matches_a_monte_carlo) {
    std::vector<double> variance;
    for (int k = 0; k < 20; ++k) {
        variance.push_back(1e-4 * (1.0 + k % 7));
    }
    const auto tv = test_total_variation(0.0, variance, 1.0, 2);
    std::mt19937_64 rng(7);
    std::normal_distribution<double> unit(0.0, 1.0);
    std::vector<double> norms;
    for (int t = 0; t < 40000; ++t) {
        double s = 0.0;
        for (const double v : variance) {
            s += 0.5 * std::abs(std::sqrt(v) * unit(rng));
        }
        norms.push_back(s);
    }
    std::sort(norms.begin(), norms.end());
    const double tv95 = norms[static_cast<std::size_t>(0.95 * norms.size())];
    BOOST_TEST(std::abs(tv.ci_high - tv95) < 0.03 * tv95);
    BOOST_TEST(tv.zero_bound == tv.ci_high);  // at D = 0 the bound is q
}

BOOST_AUTO_TEST_CASE(total_variation_decisions_follow_the_interval) {
    const std::vector<double> variance(10, 1e-6);  // noise norm ~ 0.004
    BOOST_TEST(static_cast<int>(test_total_variation(0.01, variance, 0.05, 2).decision) ==
               static_cast<int>(Decision::Agree));
    BOOST_TEST(static_cast<int>(test_total_variation(0.20, variance, 0.05, 2).decision) ==
               static_cast<int>(Decision::Differ));
    const auto mid = test_total_variation(0.05, variance, 0.05, 2);
    BOOST_TEST(static_cast<int>(mid.decision) == static_cast<int>(Decision::Inconclusive));
    BOOST_TEST(mid.ci_low >= 0.0);
}

BOOST_AUTO_TEST_CASE(noise_variance_is_the_variance_of_the_mean_difference) {
    const std::vector<std::vector<double>> a{{1.0, 2.0}, {3.0, 2.0}};
    const std::vector<std::vector<double>> b{{0.0, 1.0}, {2.0, 1.0}, {4.0, 1.0}};
    const auto v = noise_variance(a, b);
    // bin 0: s_a² = 2, s_b² = 4: 2/2 + 4/3; bin 1: 0.
    BOOST_TEST(close(v[0], 1.0 + 4.0 / 3.0));
    BOOST_TEST(v[1] == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
