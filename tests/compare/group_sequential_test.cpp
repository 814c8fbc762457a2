// The group-sequential design (group_sequential.hpp): its spending function against the
// closed form, its boundaries against an independent quadrature of the canonical joint
// normal law (two and three looks) and against Monte Carlo paths (eleven looks), and the
// look schedule.
#include <boost/math/distributions/normal.hpp>
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "sgmp/report/group_sequential.hpp"

using namespace sgmp::report;

namespace {

const boost::math::normal kUnit;

double phi(double x) {
    return boost::math::pdf(kUnit, x);
}
double upper(double x) {
    return boost::math::cdf(boost::math::complement(kUnit, x));
}

/// Composite Simpson's rule of f on [a, b] with `intervals` (even) intervals.
template <class F>
double simpson(const F& f, double a, double b, int intervals) {
    const double h = (b - a) / intervals;
    double sum = f(a) + f(b);
    for (int i = 1; i < intervals; ++i) {
        sum += f(a + i * h) * (i % 2 == 1 ? 4.0 : 2.0);
    }
    return sum * h / 3.0;
}

/// The looks of the default design: 3 seeds first (scripts/run's default), blocks of 5, up
/// to 50, against 5 reference pours.
std::vector<std::size_t> default_looks() {
    return look_schedule({3, 5, 50, 0.05}, 3);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(group_sequential)

BOOST_AUTO_TEST_CASE(spending_is_the_obrien_fleming_closed_form) {
    const double z = boost::math::quantile(kUnit, 1.0 - 0.025);
    for (const double t : {0.1, 0.3, 0.5, 0.75, 0.9}) {
        BOOST_TEST(std::abs(spent_alpha(t, 0.05) - 2.0 * upper(z / std::sqrt(t))) < 1e-12);
    }
    BOOST_TEST(std::abs(spent_alpha(1.0, 0.05) - 0.05) < 1e-12);
    BOOST_TEST(spent_alpha(0.0, 0.05) == 0.0);
}

BOOST_AUTO_TEST_CASE(the_schedule_looks_every_block_and_at_the_seeds_there_are) {
    BOOST_TEST(
        default_looks() == (std::vector<std::size_t>{3, 8, 13, 18, 23, 28, 33, 38, 43, 48, 50}),
        boost::test_tools::per_element());
    // 7 seeds, off the grid: an unplanned look at 7 between 3 and 8.
    BOOST_TEST(
        look_schedule({3, 5, 20, 0.05}, 7) == (std::vector<std::size_t>{3, 7, 8, 13, 18, 20}),
        boost::test_tools::per_element());
    // More seeds than the maximum: the last look is at the seeds there are.
    BOOST_TEST(look_schedule({5, 5, 10, 0.05}, 12) == (std::vector<std::size_t>{5, 10, 12}),
               boost::test_tools::per_element());
    // First look at the maximum: one look, the fixed-sample test.
    BOOST_TEST(look_schedule({5, 5, 5, 0.05}, 5) == (std::vector<std::size_t>{5}),
               boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(one_look_is_the_fixed_sample_test) {
    const auto looks = boundaries({5}, 5, 0.05);
    BOOST_REQUIRE(looks.size() == 1u);
    BOOST_TEST(std::abs(looks[0].boundary - boost::math::quantile(kUnit, 0.95)) < 1e-9);
    BOOST_TEST(std::abs(looks[0].nominal_alpha - 0.05) < 1e-12);
}

// Two looks: P(Z₁ > c₁) + ∫_{−∞}^{c₁} φ(u) Q((c₂ − ρu)/√(1 − ρ²)) du = α(t₂), ρ = √(I₁/I₂),
// by Simpson's rule on 40,000 intervals (its own error below 10⁻¹²). The library carries
// the score's sub-probability as a histogram (cells 0.01 sd wide, mass uniform in a cell),
// whose error in the spent α was measured at 8·10⁻⁷ (two looks) and 7·10⁻⁷ (three) on these
// designs, always below α (boundaries a little high: conservative); 2·10⁻⁶ bounds it.
BOOST_AUTO_TEST_CASE(two_looks_match_an_independent_quadrature) {
    for (const std::size_t reference : {5u, 20u}) {
        const auto looks = boundaries({3, 50}, reference, 0.05);
        const double rho = std::sqrt(information(3, reference) / information(50, reference));
        const double c1 = looks[0].boundary;
        const double c2 = looks[1].boundary;
        const double spent =
            upper(c1) +
            simpson(
                [&](double u) { return phi(u) * upper((c2 - rho * u) / std::sqrt(1 - rho * rho)); },
                -12.0, c1, 40000);
        BOOST_TEST_MESSAGE("n_B " << reference << ": c = " << c1 << ", " << c2
                                  << "; spent by quadrature " << spent);
        BOOST_TEST(std::abs(upper(c1) - spent_alpha(looks[0].fraction, 0.05)) < 1e-9);
        BOOST_TEST(std::abs(spent - 0.05) < 2e-6);
        BOOST_TEST(c2 < boost::math::quantile(kUnit, 0.95) + 0.2);  // near the fixed test's
        BOOST_TEST(c1 > c2);  // O'Brien–Fleming: strict early
    }
}

// Three looks by a double Simpson quadrature (800 × 800 intervals on [−10, c] each, its own
// error below 10⁻⁸): P(Z₁ ≤ c₁, Z₂ ≤ c₂, Z₃ > c₃) against the spent increment α(t₃) − α(t₂).
BOOST_AUTO_TEST_CASE(three_looks_match_an_independent_quadrature) {
    const std::size_t reference = 5;
    const std::vector<std::size_t> n{3, 8, 13};
    const auto looks = boundaries(n, reference, 0.05);
    const double i1 = information(n[0], reference);
    const double i2 = information(n[1], reference);
    const double i3 = information(n[2], reference);
    const double r12 = std::sqrt(i1 / i2);
    const double r23 = std::sqrt(i2 / i3);
    const double s12 = std::sqrt(1 - r12 * r12);
    const double s23 = std::sqrt(1 - r23 * r23);
    const double c1 = looks[0].boundary;
    const double c2 = looks[1].boundary;
    const double c3 = looks[2].boundary;
    const double third = simpson(
        [&](double u) {
            return phi(u) * simpson(
                                [&](double v) {
                                    return phi((v - r12 * u) / s12) / s12 *
                                           upper((c3 - r23 * v) / s23);
                                },
                                -10.0, c2, 800);
        },
        -10.0, c1, 800);
    const double increment = looks[2].alpha_spent - looks[1].alpha_spent;
    BOOST_TEST_MESSAGE("c = " << c1 << ", " << c2 << ", " << c3 << "; third look spends " << third
                              << " of " << increment);
    BOOST_TEST(std::abs(third - increment) < 2e-6);
}

// Eleven looks (the default design): canonical paths Z_k = S_k/√I_k, S a Gaussian random
// walk with increments of variance I_k − I_{k−1}. 400,000 paths: the share that crossed by
// look k has binomial sd ≤ √(0.05·0.95/400000) = 3.4·10⁻⁴; it must lie within 4 sd of α(t_k).
BOOST_AUTO_TEST_CASE(monte_carlo_paths_cross_as_spent) {
    const std::size_t reference = 5;
    const auto n = default_looks();
    const auto looks = boundaries(n, reference, 0.05);
    std::mt19937_64 random(20261207);
    std::normal_distribution<double> normal;
    constexpr int kPaths = 400000;
    std::vector<int> crossed(n.size(), 0);
    for (int p = 0; p < kPaths; ++p) {
        double s = 0.0;
        double info_before = 0.0;
        for (std::size_t k = 0; k < n.size(); ++k) {
            const double info = information(n[k], reference);
            s += std::sqrt(info - info_before) * normal(random);
            info_before = info;
            if (s / std::sqrt(info) > looks[k].boundary) {
                for (std::size_t j = k; j < n.size(); ++j) {
                    ++crossed[j];
                }
                break;
            }
        }
    }
    for (std::size_t k = 0; k < n.size(); ++k) {
        const double share = static_cast<double>(crossed[k]) / kPaths;
        const double sd = std::sqrt(looks[k].alpha_spent * (1 - looks[k].alpha_spent) / kPaths);
        BOOST_TEST_MESSAGE("look " << k + 1 << " n " << n[k] << " t " << looks[k].fraction << " c "
                                   << looks[k].boundary << " nominal " << looks[k].nominal_alpha
                                   << " spent " << looks[k].alpha_spent << " crossed " << share);
        BOOST_TEST(std::abs(share - looks[k].alpha_spent) <= 4.0 * std::max(sd, 1e-5));
    }
}

BOOST_AUTO_TEST_CASE(many_looks_stay_finite_and_spend_alpha) {
    // --max-seeds 10⁴: 2000 looks, the last ones tiny steps of information.
    const auto n = look_schedule({5, 5, 10000, 0.05}, 5);
    BOOST_REQUIRE(n.size() == 2000u);
    const auto looks = boundaries(n, 5, 0.05);
    BOOST_TEST(std::abs(looks.back().alpha_spent - 0.05) < 1e-12);
    for (const auto& l : looks) {
        BOOST_TEST(std::isfinite(l.boundary));
        BOOST_TEST(l.nominal_alpha <= 0.05);
    }
}

BOOST_AUTO_TEST_CASE(bad_schedules_are_refused) {
    BOOST_CHECK_THROW(boundaries({}, 5, 0.05), std::invalid_argument);
    BOOST_CHECK_THROW(boundaries({5, 5}, 5, 0.05), std::invalid_argument);
    BOOST_CHECK_THROW(boundaries({0, 5}, 5, 0.05), std::invalid_argument);
    BOOST_CHECK_THROW(boundaries({3, 5}, 0, 0.05), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
