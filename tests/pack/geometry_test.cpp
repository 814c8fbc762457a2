#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/pack.hpp"
#include "sgmp/pack/pack_origin.hpp"

using namespace sgmp;

BOOST_AUTO_TEST_SUITE(geometry)

BOOST_AUTO_TEST_CASE(sizing_rule_fills_a_third_of_the_particles_into_the_control_volume) {
    // (N/3)(π/6)d³ = φ*, exact up to rounding of cbrt (relative 1e-14).
    for (const std::size_t n : {150u, 300u, 1002u, 9000u, 100000u}) {
        const double d = diameter_for_count(n, 0.63);
        const double phi = (static_cast<double>(n) / 3.0) * std::numbers::pi / 6.0 * d * d * d;
        BOOST_TEST(phi == 0.63, boost::test_tools::tolerance(1e-14));
    }
    // The thesis' 1002-particle runs: d ≈ 0.1533.
    BOOST_TEST(diameter_for_count(1002) == 0.1533, boost::test_tools::tolerance(1e-3));
    BOOST_CHECK_THROW(diameter_for_count(0), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(container_text_round_trips_and_rejects_bad_text) {
    const Container thesis;
    BOOST_TEST(thesis.to_string() == "-0.625 0.625 -0.625 0.625 -0.625");
    const Container parsed = Container::parse(thesis.to_string());
    BOOST_TEST(parsed.x_min == thesis.x_min);
    BOOST_TEST(parsed.floor == thesis.floor);
    BOOST_CHECK_THROW(Container::parse("-0.625 0.625 -0.625 0.625"), std::invalid_argument);
    BOOST_CHECK_THROW(Container::parse("-0.625 0.625 -0.625 0.625 -0.625 7"),
                      std::invalid_argument);
    BOOST_CHECK_THROW(Container::parse("0.625 -0.625 -0.625 0.625 -0.625"), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(penetration_measures_the_deepest_crossing) {
    const Container c;
    BOOST_TEST(c.penetration(Vec3(0, 0, 0), 0.1) == 0.0);
    BOOST_TEST(c.penetration(Vec3(0.6, 0, 0), 0.05) == 0.025, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(c.penetration(Vec3(0, -0.6, 0), 0.05) == 0.025, boost::test_tools::tolerance(1e-12));
    // Touching a wall is not a penetration.
    BOOST_TEST(c.penetration(Vec3(-0.575, 0, 0), 0.05) == 0.0, boost::test_tools::tolerance(1e-15));
    // No lid: a sphere high above the container is inside.
    BOOST_TEST(c.penetration(Vec3(0, 40.0, 0), 0.05) == 0.0);
}

BOOST_AUTO_TEST_CASE(box_membership_and_volume) {
    const Box cv = control_volume();
    BOOST_TEST(cv.volume() == 1.0);
    BOOST_TEST(cv.contains(Vec3(0.5, -0.5, 0.0)));
    BOOST_TEST(!cv.contains(Vec3(0.5001, 0.0, 0.0)));
    BOOST_TEST(Container{}.box_up_to(1.0).contains(cv));
    BOOST_TEST(!cv.contains(Container{}.box_up_to(1.0)));
}

BOOST_AUTO_TEST_CASE(mean_diameter_of_a_polydisperse_pack) {
    Pack pack;
    pack.particles = {Particle{1, Vec3::Zero(), 0.1, 0}, Particle{2, Vec3::Zero(), 0.3, 0}};
    BOOST_TEST(mean_diameter(pack) == 0.4, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(mean_diameter(Pack{}) == 0.0);
}

BOOST_AUTO_TEST_CASE(moving_the_corner_to_the_origin_keeps_every_distance) {
    // The thesis container's corner (-0.625, -0.625, -0.625) goes to 0: centres move by
    // +0.625 on every axis, distances stay bit for bit (a shift by a power-of-two multiple
    // here), the container becomes [0, 1.25] x [0, ...) x [0, 1.25], the shift is recorded.
    Pack pack;
    pack.particles = {Particle{1, Vec3(0.1, -0.5, 0.2), 0.05, 0},
                      Particle{2, Vec3(-0.3, -0.4, 0.0), 0.05, 0}};
    pack.metadata.set("container", Container{}.to_string());
    const double before = (pack.particles[0].center - pack.particles[1].center).norm();
    const Vec3 shift = move_corner_to_origin(pack);
    BOOST_TEST(shift == Vec3::Constant(0.625));
    BOOST_TEST(pack.particles[0].center.y() == -0.5 + 0.625);
    BOOST_TEST(std::abs((pack.particles[0].center - pack.particles[1].center).norm() - before) <=
               1e-15);
    BOOST_TEST(*pack.metadata.get("container") == "0 1.25 0 1.25 0");
    BOOST_TEST(*pack.metadata.get("origin_shift") == "0.625 0.625 0.625");
}

BOOST_AUTO_TEST_SUITE_END()
