// free_runs starts from the previous call's runs: along a slide (the same spheres, the sweep
// centre moving a little each call) the runs must still be exactly those of testing every
// sample, whether the guesses hold, are off by a few samples, or belong to other spheres.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "sgmp/engine/free_arcs.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

/// The constraint of a sphere at centre offset (dx, dy, dz) from the sweep centre (contact
/// distance 1, sweep radius s), as the protocol builds it.
Blocker sphere_at(double dx, double dy, double dz, double s) {
    return Blocker{-2 * s * dx, -2 * s * dz, 1.0 - (dx * dx + dy * dy + dz * dz) - s * s};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(free_run_guesses)

BOOST_AUTO_TEST_CASE(runs_along_a_slide_match_sample_by_sample_testing) {
    Random rng(23);
    int compared = 0;
    int guided = 0;  // calls answered from runs, without testing every sample
    for (const int n : {8, 120, 720}) {
        const SweepTable table(n);
        for (int slide = 0; slide < 60; ++slide) {
            const double s = rng.uniform(0.01, 0.1);
            // Two to four spheres around a centre that drifts by up to a sweep radius per
            // call, with one sphere sometimes dropped or added (the guesses then shift).
            struct Ball {
                double x, y, z;
            };
            std::vector<Ball> balls;
            const int count = 2 + static_cast<int>(rng.below(3));
            for (int i = 0; i < count; ++i) {
                const double polar = rng.uniform(0.3, 2.0);
                const double azimuth = rng.uniform(0.0, 2 * std::numbers::pi);
                const double distance = rng.uniform(0.98, 1.02);
                balls.push_back({distance * std::sin(polar) * std::sin(azimuth),
                                 -distance * std::cos(polar),
                                 distance * std::sin(polar) * std::cos(azimuth)});
            }
            double cx = 0.0;
            double cz = 0.0;
            FreeRuns fast;
            FreeRuns slow;
            for (int step = 0; step < 40; ++step) {
                const double angle = rng.uniform(0.0, 2 * std::numbers::pi);
                const double length = s * rng.uniform(0.0, 1.0);
                cx += length * std::sin(angle);
                cz += length * std::cos(angle);
                std::vector<Blocker> blockers;
                for (std::size_t i = 0; i < balls.size(); ++i) {
                    if (i == 0 && step % 7 == 3) {
                        continue;  // a sphere leaves the list for one call
                    }
                    blockers.push_back(sphere_at(balls[i].x - cx, balls[i].y, balls[i].z - cz, s));
                }
                free_runs(table, blockers, fast);
                free_runs_by_samples(table, blockers, slow);
                BOOST_TEST_INFO("n " << n << ", slide " << slide << ", step " << step);
                BOOST_TEST((fast.start == slow.start && fast.length == slow.length &&
                            fast.free_count == slow.free_count));
                guided += fast.guess_positions == n ? 1 : 0;
                ++compared;
            }
        }
    }
    BOOST_TEST(compared == 3 * 60 * 40);
    BOOST_TEST(guided > compared / 10);  // not only the sample-by-sample fallback (1576 of 7200)
}

BOOST_AUTO_TEST_SUITE_END()
