// The arc computation of free sweep samples agrees exactly with testing every sample.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "sgmp/engine/free_arcs.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

bool same_runs(const FreeRuns& x, const FreeRuns& y) {
    return x.start == y.start && x.length == y.length && x.free_count == y.free_count;
}

/// Constraints like a sweep's: spheres at random offsets near contact, sweep radius s.
std::vector<Blocker> random_spheres(Random& rng, int count, double s) {
    std::vector<Blocker> blockers;
    for (int i = 0; i < count; ++i) {
        const double contact = 1.0;
        // Centre distances within [contact − s/2, contact + s]: from touching to out of reach.
        const double distance = rng.uniform(contact - 0.5 * s, contact + s);
        const double polar = rng.uniform(0.0, M_PI);
        const double azimuth = rng.uniform(0.0, 2 * M_PI);
        const double dx = distance * std::sin(polar) * std::sin(azimuth);
        const double dy = distance * std::cos(polar);
        const double dz = distance * std::sin(polar) * std::cos(azimuth);
        blockers.push_back(Blocker{2 * s * dx, 2 * s * dz,
                                   contact * contact - (dx * dx + dy * dy + dz * dz) - s * s});
    }
    return blockers;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(free_arcs)

BOOST_AUTO_TEST_CASE(arcs_match_sample_by_sample_testing) {
    Random rng(17);
    int compared = 0;
    for (const int n : {3, 4, 7, 8, 120, 721, 100000}) {
        const SweepTable table(n);
        FreeRuns fast;
        FreeRuns slow;
        for (int trial = 0; trial < (n > 1000 ? 40 : 400); ++trial) {
            const auto blockers =
                random_spheres(rng, static_cast<int>(rng.below(5)), rng.uniform(0.005, 0.2));
            free_runs(table, blockers, fast);
            free_runs_by_samples(table, blockers, slow);
            BOOST_TEST_INFO("n " << n << ", trial " << trial);
            BOOST_TEST(same_runs(fast, slow));
            ++compared;
        }
    }
    BOOST_TEST(compared > 2000);
}

BOOST_AUTO_TEST_CASE(special_cases_match_too) {
    const SweepTable table(120);
    FreeRuns fast;
    FreeRuns slow;
    const std::vector<std::vector<Blocker>> cases = {
        {},                                // nothing: every sample free
        {Blocker{0.0, 0.0, 1.0}},          // blocks everything
        {Blocker{0.0, 0.0, -1.0}},         // blocks nothing
        {Blocker{1.0, 0.0, 1.0 - 1e-9}},   // tangent: only the samples near +x are free
        {Blocker{1.0, 0.0, -1.0 + 1e-9}},  // tangent: only sample at −x is blocked
        {Blocker{0.0, 1.0, 0.0}},          // half the circle (z < 0) blocked
        {Blocker{-1.0, 0.0, -0.3}, Blocker{1.0, 0.0, -0.3}},  // two walls facing
        {Blocker{0.3, 0.4, 0.49}},                            // a narrow free arc
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        free_runs(table, cases[i], fast);
        free_runs_by_samples(table, cases[i], slow);
        BOOST_TEST_INFO("case " << i);
        BOOST_TEST(same_runs(fast, slow));
    }
    free_runs(table, {}, fast);
    BOOST_TEST(fast.free_count == 120);
    free_runs(table, {Blocker{0.0, 1.0, 0.0}}, fast);
    // z = cos θ < 0 for θ in (90°, 270°): samples 31..89 blocked (30 and 90 have z ≈ ±6e-17).
    BOOST_TEST(fast.free_count >= 60);
    BOOST_TEST(fast.free_count <= 62);
}

BOOST_AUTO_TEST_SUITE_END()
