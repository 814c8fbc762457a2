// Horizontal jitter of starting arrangements: small, horizontal, inside, never overlapping.
#include <boost/test/unit_test.hpp>

#include "sgmp/reference/start_jitter.hpp"

using namespace sgmp;
using namespace sgmp::reference;

BOOST_AUTO_TEST_SUITE(start_jitter)

BOOST_AUTO_TEST_CASE(a_column_is_moved_sideways_only_and_by_little) {
    const double r = 0.05;
    std::vector<Vec3> centers;
    for (int i = 0; i < 20; ++i) {
        centers.emplace_back(0.0, -0.625 + r + 1.2 * 2.0 * r * i, 0.0);
    }
    const std::vector<Vec3> before = centers;
    Random random(1);
    BOOST_TEST(jitter_horizontally(centers, r, 0.001, Container{}, random) == 20u);
    for (std::size_t i = 0; i < centers.size(); ++i) {
        BOOST_TEST(centers[i].y() == before[i].y());
        const double shift = (centers[i] - before[i]).norm();
        BOOST_TEST(shift > 0.0);
        BOOST_TEST(shift <= 0.001);
    }
}

BOOST_AUTO_TEST_CASE(touching_spheres_never_end_overlapping_or_outside) {
    // A row of touching spheres from wall to wall: every move would overlap a neighbour or
    // cross a wall, except where the row leaves room.
    const double r = 0.125;
    std::vector<Vec3> centers;
    for (int i = 0; i < 5; ++i) {
        centers.emplace_back(-0.625 + r + 2.0 * r * i, -0.5, 0.0);
    }
    Random random(2);
    jitter_horizontally(centers, r, 0.02, Container{}, random);
    for (std::size_t i = 0; i < centers.size(); ++i) {
        BOOST_TEST(Container{}.penetration(centers[i], r) == 0.0);
        for (std::size_t j = i + 1; j < centers.size(); ++j) {
            BOOST_TEST((centers[i] - centers[j]).norm() >= 2.0 * r);
        }
    }
}

BOOST_AUTO_TEST_CASE(zero_amplitude_keeps_the_arrangement) {
    std::vector<Vec3> centers{Vec3(0.0, 0.0, 0.0)};
    Random random(3);
    BOOST_TEST(jitter_horizontally(centers, 0.1, 0.0, Container{}, random) == 0u);
    BOOST_TEST(centers[0] == Vec3(0.0, 0.0, 0.0));
}

BOOST_AUTO_TEST_SUITE_END()
