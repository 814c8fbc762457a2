// The mixing profile of a blend: slab volumes against the box-cut closed form, and beds
// with known answers.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "sgmp/metrics/mixing_profile.hpp"
#include "sgmp/pack/ball_cut.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;
using namespace sgmp::metrics;

namespace {

Particle sphere(double x, double y, double z, double r, int species) {
    Particle p;
    p.center = Vec3(x, y, z);
    p.radius = r;
    p.species = species;
    return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mixing)

BOOST_AUTO_TEST_CASE(slab_volumes_equal_the_box_cut_closed_form) {
    // An independent path: ball_cut_volume with x bounds wider than the ball (1e-12 of
    // the ball: both are closed forms in double precision).
    Random rng(5);
    for (int k = 0; k < 500; ++k) {
        const double r = rng.uniform(0.01, 1.0);
        const double c = rng.uniform(-1.0, 1.0);
        const double y0 = rng.uniform(-2.0, 2.0);
        const double y1 = y0 + rng.uniform(0.0, 2.0);
        const double ours = ball_slab_volume(r, c, y0, y1);
        const double theirs = ball_cut_volume(r, -2.0 * r, 2.0 * r, y0 - c, y1 - c);
        BOOST_TEST(std::abs(ours - theirs) <= 1e-12 * r * r * r);
    }
    BOOST_TEST(ball_slab_volume(1.0, 0.0, -5.0, 5.0) == 4.0 / 3.0 * std::numbers::pi,
               boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(a_layered_bed_is_unmixed_and_an_alternating_one_mixed) {
    // Four layers of 0.1-radius spheres stacked at heights 0.1, 0.3, 0.5, 0.7, 0.9 (the
    // fifth is the left-out top layer): bed [0, 0.8], quarters of 0.2, each holding one
    // layer exactly.
    std::vector<Particle> layered;
    std::vector<Particle> alternating;
    for (int layer = 0; layer < 5; ++layer) {
        for (int i = 0; i < 4; ++i) {
            const double x = -0.3 + 0.2 * i;
            const double y = 0.1 + 0.2 * layer;
            layered.push_back(sphere(x, y, 0.0, 0.1, layer < 2 ? 1 : 2));
            alternating.push_back(sphere(x, y, 0.0, 0.1, 1 + i % 2));
        }
    }
    const auto unmixed = mixing_profile(layered, 0.0);
    BOOST_TEST_REQUIRE(unmixed.has_value());
    BOOST_TEST(unmixed->y_high == 0.8, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(unmixed->quarters[0][0] == 1.0);
    BOOST_TEST(unmixed->quarters[3][1] == 1.0);
    BOOST_TEST(unmixed->overall[0] == 0.5, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(unmixed->deviation == 0.5, boost::test_tools::tolerance(1e-12));
    const auto mixed = mixing_profile(alternating, 0.0);
    BOOST_TEST_REQUIRE(mixed.has_value());
    BOOST_TEST(mixed->deviation < 1e-12);
    // One species: no profile.
    for (Particle& p : layered) {
        p.species = 0;
    }
    BOOST_TEST(!mixing_profile(layered, 0.0).has_value());
}

BOOST_AUTO_TEST_SUITE_END()
