#include "sgmp/pack/sphere_box_volume.hpp"

#include <algorithm>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "sgmp/pack/ball_cut.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
double ball(double r) {
    return 4.0 / 3.0 * kPi * r * r * r;
}
/// Volume of the cap of height h of a sphere of radius r: πh²(3r − h)/3.
double cap(double r, double h) {
    return kPi * h * h * (3.0 * r - h) / 3.0;
}
Box box(double x0, double x1, double y0, double y1, double z0, double z1) {
    return Box{Vec3(x0, y0, z0), Vec3(x1, y1, z1)};
}
// Quadrature is asked for 1e-14 relative per piece; 1e-12 of the ball volume leaves
// room for a few pieces' rounding.
const auto kTight = boost::test_tools::tolerance(1e-12);
}  // namespace

BOOST_AUTO_TEST_SUITE(sphere_box_volume_suite)

BOOST_AUTO_TEST_CASE(inside_and_outside) {
    BOOST_TEST(sphere_box_volume(Vec3::Zero(), 0.1, control_volume()) == ball(0.1), kTight);
    BOOST_TEST(sphere_box_volume(Vec3(0.7, 0, 0), 0.1, control_volume()) == 0.0);
    // Near a corner but outside it: the nearest box point is farther than r.
    BOOST_TEST(sphere_box_volume(Vec3(0.58, 0.58, 0.58), 0.1, control_volume()) == 0.0);
    BOOST_TEST(sphere_box_volume(Vec3::Zero(), 0.0, control_volume()) == 0.0);
}

BOOST_AUTO_TEST_CASE(a_sphere_holding_the_whole_box_gives_the_box_for_any_radius) {
    // Radii whose square overflows once reached boost's quadrature with NaN slices
    // ("tanh_sinh ... evaluated your function at a singular point").
    const Box box{Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5)};
    for (const double r : {1.75, 1e10, 1e154, 1e200, 1e300, 1.7e308}) {  // the far corner: √3
        BOOST_TEST_INFO("radius " << r);
        BOOST_TEST(sphere_box_volume(Vec3(0.5, 0.5, 0.5), r, box) == 1.0);
    }
}

BOOST_AUTO_TEST_CASE(one_face_gives_the_cap) {
    const double r = 0.2;
    for (const double h : {0.01, 0.1, 0.2, 0.33, 0.39}) {
        // The face x = 0.5 cuts a cap of height h off the sphere's +x side.
        const Vec3 c(0.5 - (r - h), 0.0, 0.0);
        BOOST_TEST(sphere_box_volume(c, r, control_volume()) == ball(r) - cap(r, h), kTight);
    }
}

BOOST_AUTO_TEST_CASE(center_on_an_edge_and_a_corner) {
    const double r = 0.15;
    BOOST_TEST(sphere_box_volume(Vec3(0.5, 0.0, 0.0), r, control_volume()) == ball(r) / 2, kTight);
    BOOST_TEST(sphere_box_volume(Vec3(0.5, 0.5, 0.0), r, control_volume()) == ball(r) / 4, kTight);
    BOOST_TEST(sphere_box_volume(Vec3(0.5, 0.5, 0.5), r, control_volume()) == ball(r) / 8, kTight);
}

BOOST_AUTO_TEST_CASE(two_faces_off_center_against_the_wedge_identity) {
    // The planes x = a and y = b split the ball into four wedges; the four must add up to
    // the ball, and the two on one side of x = a to the cap there.
    const double r = 0.3;
    const double a = 0.07;
    const double b = -0.12;
    const double w1 = sphere_box_volume(Vec3::Zero(), r, box(a, kInf, b, kInf, -kInf, kInf));
    const double w2 = sphere_box_volume(Vec3::Zero(), r, box(a, kInf, -kInf, b, -kInf, kInf));
    const double w3 = sphere_box_volume(Vec3::Zero(), r, box(-kInf, a, b, kInf, -kInf, kInf));
    const double w4 = sphere_box_volume(Vec3::Zero(), r, box(-kInf, a, -kInf, b, -kInf, kInf));
    BOOST_TEST(w1 + w2 == cap(r, r - a), kTight);
    BOOST_TEST(w1 + w3 == cap(r, r - b), kTight);
    BOOST_TEST(w1 + w2 + w3 + w4 == ball(r), kTight);
    BOOST_TEST(w1 > 0.0);
}

BOOST_AUTO_TEST_CASE(any_partition_of_space_adds_up_to_the_ball) {
    // 3x3x3 boxes from two random cuts per axis: every piece uses the quadrature path with
    // up to three clipping axes; their sum must be the ball volume.
    Random random(20261122);
    for (int trial = 0; trial < 20; ++trial) {
        const double r = random.uniform(0.05, 0.5);
        double cuts[3][4];
        for (auto& axis : cuts) {
            double u = random.uniform(-r, r);
            double v = random.uniform(-r, r);
            if (u > v) {
                std::swap(u, v);
            }
            axis[0] = -kInf;
            axis[1] = u;
            axis[2] = v;
            axis[3] = kInf;
        }
        double total = 0.0;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                for (int k = 0; k < 3; ++k) {
                    const double piece =
                        sphere_box_volume(Vec3::Zero(), r,
                                          box(cuts[0][i], cuts[0][i + 1], cuts[1][j],
                                              cuts[1][j + 1], cuts[2][k], cuts[2][k + 1]));
                    BOOST_TEST(piece >= 0.0);
                    total += piece;
                }
            }
        }
        BOOST_TEST(total == ball(r), kTight);
    }
}

BOOST_AUTO_TEST_CASE(two_clipped_axes_closed_form_against_quadrature_of_slices) {
    // Independent route: ∫ A(z) dz over the slices z ∈ [−r, r] (uncut axis), A the closed-form
    // area of the slice disk inside the x–y rectangle, by tanh–sinh between the break points
    // z = ±√(r² − e²) of each edge line e. Quadrature asked for 1e-14 per piece: 1e-12 of
    // the ball.
    boost::math::quadrature::tanh_sinh<double> integrator;
    Random random(20261202);
    for (int trial = 0; trial < 2000; ++trial) {
        const double r = random.uniform(0.01, 1.0);
        const double x0 = random.uniform(-1.2 * r, r);
        const double x1 = random.uniform(x0, 1.2 * r);
        const double y0 = random.uniform(-1.2 * r, r);
        const double y1 = random.uniform(y0, 1.2 * r);
        std::vector<double> breaks{-r, r};
        for (const double e : {x0, x1, y0, y1}) {
            if (std::abs(e) < r) {
                breaks.push_back(std::sqrt(r * r - e * e));
                breaks.push_back(-breaks.back());
            }
        }
        for (const double ex : {x0, x1}) {
            for (const double ey : {y0, y1}) {
                if (ex * ex + ey * ey < r * r) {
                    breaks.push_back(std::sqrt(r * r - ex * ex - ey * ey));
                    breaks.push_back(-breaks.back());
                }
            }
        }
        std::sort(breaks.begin(), breaks.end());
        const auto slice = [&](double z) {
            return disk_rectangle_area(std::sqrt(std::max(0.0, r * r - z * z)), x0, x1, y0, y1);
        };
        double reference = 0.0;
        for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
            if (breaks[i + 1] > breaks[i]) {
                reference += integrator.integrate(slice, breaks[i], breaks[i + 1], 1e-14);
            }
        }
        BOOST_TEST(std::abs(ball_cut_volume(r, x0, x1, y0, y1) - reference) <= 1e-12 * ball(r));
        const Box clipping = box(x0, x1, y0, y1, -kInf, kInf);
        BOOST_TEST(std::abs(sphere_box_volume(Vec3::Zero(), r, clipping) - reference) <=
                   1e-12 * ball(r));
    }
}

BOOST_AUTO_TEST_CASE(disk_rectangle_area_cases) {
    const double rho = 0.5;
    BOOST_TEST(disk_rectangle_area(rho, -1, 1, -1, 1) == kPi * rho * rho, kTight);
    BOOST_TEST(disk_rectangle_area(rho, 0, 1, 0, 1) == kPi * rho * rho / 4, kTight);
    BOOST_TEST(disk_rectangle_area(rho, -0.1, 0.1, -0.1, 0.1) == 0.04, kTight);
    BOOST_TEST(disk_rectangle_area(rho, 0.6, 1, -1, 1) == 0.0);
    // Segment beyond the chord y = 0.25: ρ²acos(h/ρ) − h√(ρ²−h²).
    const double h = 0.25;
    const double segment = rho * rho * std::acos(h / rho) - h * std::sqrt(rho * rho - h * h);
    BOOST_TEST(disk_rectangle_area(rho, h, 1, -1, 1) == segment, kTight);
}

BOOST_AUTO_TEST_SUITE_END()
