// Volumes of a sphere cut by one, two and three faces against closed forms; this checks
// sgmp::sphere_box_volume of the pack library with both quadratures (tanh–sinh, the default;
// Gauss–Legendre, which the metrics use for shells and slabs).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "sgmp/pack/random.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"

using namespace sgmp;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kBig = 1e3;
double ball(double r) {
    return 4.0 / 3.0 * kPi * r * r * r;
}
/// Cap of height h: πh²(3r − h)/3.
double cap(double r, double h) {
    return kPi * h * h * (3.0 * r - h) / 3.0;
}
/// The half-space x ≥ a (other axes unbounded).
Box above_x(double a) {
    return Box{Vec3(a, -kBig, -kBig), Vec3(kBig, kBig, kBig)};
}
// sphere_box_volume promises ~1e-13 of the ball; closed forms here are ~1e-14.
constexpr double kExact = 1e-12;
// The Gauss–Legendre three-face quadrature: ~1e-11 of the ball.
constexpr double kQuadrature = 1e-10;
double exact_volume(const Vec3& c, double r, const Box& box) {
    return sphere_box_volume(c, r, box);
}
double fast_volume(const Vec3& c, double r, const Box& box) {
    return sphere_box_volume(c, r, box, SphereBoxQuadrature::GaussLegendre);
}
}  // namespace

BOOST_AUTO_TEST_SUITE(volumes)

BOOST_AUTO_TEST_CASE(one_face_is_the_cap) {
    const Vec3 c(0.3, -0.2, 0.1);
    const double r = 0.25;
    for (const double h : {0.001, 0.05, 0.25, 0.4, 0.499}) {
        const Box box = above_x(c.x() + r - h);
        BOOST_TEST(std::abs(sphere_box_volume(c, r, box) - cap(r, h)) <= kExact * ball(r));
        BOOST_TEST(std::abs(fast_volume(c, r, box) - cap(r, h)) <= kExact * ball(r));
    }
}

BOOST_AUTO_TEST_CASE(center_on_an_edge_is_a_quarter_and_on_a_corner_an_eighth) {
    const double r = 0.3;
    const Vec3 c(0.1, 0.2, 0.3);
    const Box edge{Vec3(0.1, 0.2, -kBig), Vec3(kBig, kBig, kBig)};
    const Box corner{Vec3(0.1, 0.2, 0.3), Vec3(kBig, kBig, kBig)};
    for (const auto volume : {&exact_volume, &fast_volume}) {
        BOOST_TEST(std::abs(volume(c, r, edge) - ball(r) / 4) <= kExact * ball(r));
        BOOST_TEST(std::abs(volume(c, r, corner) - ball(r) / 8) <= kQuadrature * ball(r));
    }
}

BOOST_AUTO_TEST_CASE(off_edge_cases_by_symmetry) {
    // A face at distance a from the centre and a second face through the centre halve the
    // cap (mirror symmetry); a third face through the centre quarters it.
    const double r = 0.2;
    const Vec3 c(0.0, 0.0, 0.0);
    for (const double a : {-0.15, -0.05, 0.0, 0.07, 0.19}) {
        const double cap_volume = cap(r, r - a);
        const Box two{Vec3(a, 0.0, -kBig), Vec3(kBig, kBig, kBig)};
        const Box three{Vec3(a, 0.0, 0.0), Vec3(kBig, kBig, kBig)};
        for (const auto volume : {&exact_volume, &fast_volume}) {
            BOOST_TEST(std::abs(volume(c, r, two) - cap_volume / 2) <= kExact * ball(r));
            BOOST_TEST(std::abs(volume(c, r, three) - cap_volume / 4) <= kQuadrature * ball(r));
        }
    }
}

BOOST_AUTO_TEST_CASE(eight_boxes_around_a_point_add_up_to_the_ball) {
    const double r = 0.3;
    const Vec3 c(0.0, 0.0, 0.0);
    const Vec3 split(0.05, -0.11, 0.17);
    double sum = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        Box box{Vec3::Constant(-1.0), Vec3::Constant(1.0)};
        for (int axis = 0; axis < 3; ++axis) {
            ((corner >> axis) & 1 ? box.lo : box.hi)[axis] = split[axis];
        }
        sum += fast_volume(c, r, box);
    }
    BOOST_TEST(std::abs(sum - ball(r)) <= kQuadrature * ball(r));
}

BOOST_AUTO_TEST_CASE(both_quadratures_agree_on_random_boxes) {
    Random random(17);
    for (int i = 0; i < 3000; ++i) {
        const double r = random.uniform(0.05, 1.0);
        const Vec3 c(random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5),
                     random.uniform(-0.5, 0.5));
        Box box{Vec3(random.uniform(-1.5, 0), random.uniform(-1.5, 0), random.uniform(-1.5, 0)),
                Vec3(random.uniform(0, 1.5), random.uniform(0, 1.5), random.uniform(0, 1.5))};
        const double reference = sphere_box_volume(c, r, box);
        BOOST_TEST(std::abs(fast_volume(c, r, box) - reference) <= kQuadrature * ball(r));
    }
}

BOOST_AUTO_TEST_SUITE_END()
