// The equilibrium certificate (equilibrium_certificate.hpp) on cases with a closed-form
// answer, and on DEM pours, whose settled spheres are balanced by their contact forces.
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <cmath>
#include <random>
#include <string>

#include "sgmp/engine/coulomb_pyramid.hpp"
#include "sgmp/engine/equilibrium_certificate.hpp"
#include "sgmp/pack/pack_file.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

const Container kBox{};
constexpr double kD = 0.1;

Particle sphere(double x, double y, double z, double d = kD) {
    return Particle{0, Vec3(x, y, z), 0.5 * d, 0};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(equilibrium_certificate)

BOOST_AUTO_TEST_CASE(a_sphere_on_the_floor_is_balanced) {
    const auto c = certify_frictionless({sphere(0, kBox.floor + 0.5 * kD, 0)}, kBox, kD);
    BOOST_TEST(c.certified);
    BOOST_TEST(c.contacts == 1u);
    BOOST_TEST(c.force.at(0) == 1.0, boost::test_tools::tolerance(1e-12));  // its weight
    BOOST_TEST(c.residual_max <= 1e-12);
    BOOST_TEST(c.underconstrained == 1u);
}

BOOST_AUTO_TEST_CASE(a_floating_sphere_is_out_of_balance_by_its_weight) {
    const auto c = certify_frictionless({sphere(0, kBox.floor + 0.51 * kD, 0)}, kBox, kD);
    BOOST_TEST(!c.certified);
    BOOST_TEST(c.contacts == 0u);
    BOOST_TEST(c.residual_max == 1.0, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(a_column_carries_the_weight_above_each_contact) {
    // Three spheres stacked on the floor: the floor carries 3, the pairs 2 and 1.
    const double y0 = kBox.floor + 0.5 * kD;
    const auto c = certify_frictionless(
        {sphere(0, y0, 0), sphere(0, y0 + kD, 0), sphere(0, y0 + 2 * kD, 0)}, kBox, kD);
    BOOST_TEST(c.certified);
    BOOST_TEST_REQUIRE(c.contacts == 3u);
    double total = 0.0;
    for (const double f : c.force) {
        total += f;
    }
    // 1 + 2 + 3, to the solver's target: every residual below 10⁻⁴ m·g.
    BOOST_TEST(total == 6.0, boost::test_tools::tolerance(1e-4));
    BOOST_TEST(c.residual_max <= 1e-4);
    // A sphere half the size weighs 1/8.
    const auto small =
        certify_frictionless({sphere(0, kBox.floor + 0.25 * kD, 0, 0.5 * kD)}, kBox, kD);
    BOOST_TEST(small.force.at(0) == 0.125, boost::test_tools::tolerance(1e-3));
}

BOOST_AUTO_TEST_CASE(a_sphere_on_two_others_needs_the_walls) {
    // Two spheres on the floor, 1.6 d apart, and one resting on both: the lower ones are
    // pushed apart, so without walls nothing holds them; against the walls all balance.
    const double y0 = kBox.floor + 0.5 * kD;
    const double half = 0.8 * kD;
    const double lift = std::sqrt(kD * kD - half * half);
    const auto loose = certify_frictionless(
        {sphere(-half, y0, 0), sphere(half, y0, 0), sphere(0, y0 + lift, 0)}, kBox, kD);
    BOOST_TEST(!loose.certified);
    // Least L1 residual over f ≥ 0 (closed form for this symmetric case; the floor balances
    // the lower spheres' vertical load): pair forces f leave |R_top| = 1 − 1.2·f and a thrust
    // 0.8·f on each lower sphere, Σ|R|₁ = 1 − 1.2·f + 1.6·f, least at f = 0: the top keeps
    // its whole weight.
    BOOST_TEST(loose.residual_max == 1.0, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(loose.residual_sum == 1.0, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(loose.worst_sphere == 2u);
    Container narrow = kBox;
    narrow.x_min = -half - 0.5 * kD;
    narrow.x_max = half + 0.5 * kD;
    const auto held = certify_frictionless(
        {sphere(-half, y0, 0), sphere(half, y0, 0), sphere(0, y0 + lift, 0)}, narrow, kD);
    BOOST_TEST(held.certified);
    BOOST_TEST(held.contacts == 6u);  // 2 pairs, 2 floor, 2 walls
}

BOOST_AUTO_TEST_CASE(friction_holds_a_sphere_wedged_between_two_walls) {
    // A sphere touching both x walls and nothing below: the normal forces cancel in any
    // magnitude, so friction at any μ > 0 carries its weight (the two tangential forces
    // give opposite torques about the centre); without friction it is out of balance by
    // its weight.
    Container wedge = kBox;
    wedge.x_min = -0.5 * kD;
    wedge.x_max = 0.5 * kD;
    const std::vector<Particle> one{sphere(0, kBox.floor + 2 * kD, 0)};
    const auto held = certify_frictional(one, wedge, kD, 0.1);
    BOOST_TEST(held.certified);
    BOOST_TEST(held.contacts == 2u);
    BOOST_TEST(held.residual_max <= 1e-4);
    const auto smooth = certify_frictional(one, wedge, kD, 0.0);
    BOOST_TEST(!smooth.certified);
    BOOST_TEST(smooth.residual_max == 1.0, boost::test_tools::tolerance(1e-6));
    BOOST_TEST(!certify_frictionless(one, wedge, kD).certified);
    // On the floor it is certified with or without friction; the column too.
    const double y0 = kBox.floor + 0.5 * kD;
    BOOST_TEST(
        certify_frictional({sphere(0, y0, 0), sphere(0, y0 + kD, 0)}, kBox, kD, 0.5).certified);
    BOOST_CHECK_THROW(certify_frictional(one, wedge, kD, -0.1), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(a_witness_certifies_only_when_its_forces_balance) {
    // The column of three on the floor: floor 3, pairs 2 and 1, in m·g (closed form).
    const double y0 = kBox.floor + 0.5 * kD;
    const std::vector<Particle> column{sphere(0, y0, 0), sphere(0, y0 + kD, 0),
                                       sphere(0, y0 + 2 * kD, 0)};
    const std::vector<ContactForce> exact{{0, 0, Partner::Floor, 3.0},
                                          {1, 0, Partner::Sphere, 2.0},  // either order
                                          {1, 2, Partner::Sphere, 1.0},
                                          {2, 0, Partner::Sphere, 7.0}};  // not a contact
    const auto by_witness = certify_frictionless(column, kBox, kD, {}, exact);
    BOOST_TEST(by_witness.by_witness);
    BOOST_TEST(by_witness.certified);
    BOOST_TEST(by_witness.residual_max <= 1e-15);  // exact forces, exact geometry
    // A witness 10 % short on the floor is not enough: the LP runs and certifies, as
    // without a witness (its residual within the LP's 10⁻¹⁰ tolerances).
    std::vector<ContactForce> short_floor = exact;
    short_floor[0].force = 2.7;
    const auto by_lp = certify_frictionless(column, kBox, kD, {}, short_floor);
    const auto plain = certify_frictionless(column, kBox, kD);
    BOOST_TEST(!by_lp.by_witness);
    BOOST_TEST(by_lp.certified);
    BOOST_TEST(by_lp.residual_max == plain.residual_max, boost::test_tools::tolerance(1e-12));
    // A witness on the floating sphere cannot make it balanced.
    const auto floating =
        certify_frictionless({sphere(0, kBox.floor + 0.51 * kD, 0)}, kBox, kD, {},
                             std::vector<ContactForce>{{0, 0, Partner::Floor, 1.0}});
    BOOST_TEST(!floating.certified);
    BOOST_TEST(floating.residual_max == 1.0, boost::test_tools::tolerance(1e-12));
    BOOST_CHECK_THROW(certify_frictionless(column, kBox, kD, {},
                                           std::vector<ContactForce>{{0, 0, Partner::Floor, -1.0}}),
                      std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(pyramid_edge_forces_rebuild_any_force_inside_the_pyramid) {
    // Σₖ βₖ·Eₖ = f·n + f_t with every βₖ ≥ 0, for random normals and forces in the inscribed
    // cone (closed form: two edges either side of f_t plus an equal share on all eight).
    // Tolerance 10⁻¹²: a few roundings of numbers of order 1.
    std::mt19937_64 rng(7);
    std::normal_distribution<double> gauss;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec3 n = Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
        const double mu = trial % 10 == 0 ? 2.0 : 0.5;
        const double f = 0.01 + 3.0 * unit(rng);
        Vec3 t = Vec3(gauss(rng), gauss(rng), gauss(rng));
        t -= t.dot(n) * n;
        t *= unit(rng) * pyramid_inscribed_friction(mu) * f / t.norm();
        const auto beta = pyramid_edge_forces(n, mu, f, t + 0.3 * n);  // normal part ignored
        const auto edges = coulomb_pyramid(n, mu);
        Vec3 sum = Vec3::Zero();
        for (std::size_t k = 0; k < beta.size(); ++k) {
            BOOST_TEST_REQUIRE(beta[k] >= 0.0);
            sum += beta[k] * edges[k];
        }
        BOOST_TEST((sum - (f * n + t)).norm() <= 1e-12, "trial " << trial);
    }
    // Beyond the pyramid (|f_t| = 2·μ·f): scaled back along f_t onto the pyramid's boundary,
    // the normal part kept; every share of the rest is then 0.
    const Vec3 n(0.0, 1.0, 0.0);
    const auto beta = pyramid_edge_forces(n, 0.5, 1.0, Vec3(1.0, 0.0, 0.3));
    const auto edges = coulomb_pyramid(n, 0.5);
    Vec3 sum = Vec3::Zero();
    int nonzero = 0;
    for (std::size_t k = 0; k < beta.size(); ++k) {
        BOOST_TEST(beta[k] >= 0.0);
        sum += beta[k] * edges[k];
        nonzero += beta[k] > 0.0 ? 1 : 0;
    }
    BOOST_TEST(sum.y() == 1.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(sum.z() / sum.x() == 0.3, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(nonzero <= 2);
    BOOST_TEST(std::hypot(sum.x(), sum.z()) <= 0.5 + 1e-12);  // inside the cone at μ
    for (const double b : pyramid_edge_forces(n, 0.5, -1.0, Vec3(0.1, 0, 0))) {
        BOOST_TEST(b == 0.0);
    }
}

BOOST_AUTO_TEST_CASE(a_frictional_witness_certifies_with_its_tangential_forces) {
    // The sphere wedged between two walls, nothing below: normal forces F from each wall and
    // an upward friction of 1/2 on each side carry its weight; the two frictions' torques
    // about the centre cancel (closed form). At μ = 0.1 the inscribed cone holds 0.0854·F,
    // so F = 10 holds 0.5 with room.
    Container wedge = kBox;
    wedge.x_min = -0.5 * kD;
    wedge.x_max = 0.5 * kD;
    const std::vector<Particle> one{sphere(0, kBox.floor + 2 * kD, 0)};
    const Vec3 up(0.0, 0.5, 0.0);
    const std::vector<ContactForce> exact{{0, 0, Partner::XMin, 10.0, up},
                                          {0, 0, Partner::XMax, 10.0, up}};
    const auto held = certify_frictional(one, wedge, kD, 0.1, {}, exact);
    BOOST_TEST(held.by_witness);
    BOOST_TEST(held.certified);
    BOOST_TEST(held.residual_max <= 1e-14);
    BOOST_TEST(held.force.at(0) == 10.0, boost::test_tools::tolerance(1e-12));
    // At μ = 0.05 the pyramid holds at most 0.0462·10 < 0.5 a side: the witness is scaled
    // into it and falls short; the LP then finds larger normal forces and certifies.
    const auto scaled = certify_frictional(one, wedge, kD, 0.05, {}, exact);
    BOOST_TEST(!scaled.by_witness);
    BOOST_TEST(scaled.certified);
    // Without the tangential forces the witness cannot hold the sphere.
    const std::vector<ContactForce> normal_only{{0, 0, Partner::XMin, 10.0},
                                                {0, 0, Partner::XMax, 10.0}};
    BOOST_TEST(!certify_frictional(one, wedge, kD, 0.1, {}, normal_only).by_witness);
}

BOOST_AUTO_TEST_CASE(a_frictional_witness_means_the_same_named_from_either_sphere) {
    // A pair on the floor, side by side, with a tangential force that balances nothing:
    // naming the contact (0, 1) with f_t on sphere 0, or (1, 0) with −f_t on sphere 1, is one
    // force, so the residuals are the same to the last bit. (A residual tolerance of 10 m·g
    // lets the witness stand, so its own residuals are reported, not the LP's.)
    const double y0 = kBox.floor + 0.5 * kD;
    const std::vector<Particle> pair{sphere(0, y0, 0), sphere(kD, y0, 0)};
    const Vec3 t(0.0, 0.02, 0.03);
    const std::vector<ContactForce> from_0{
        {0, 1, Partner::Sphere, 0.2, t}, {0, 0, Partner::Floor, 1.0}, {1, 0, Partner::Floor, 1.0}};
    std::vector<ContactForce> from_1 = from_0;
    from_1[0] = {1, 0, Partner::Sphere, 0.2, Vec3(-t)};
    const CertificateOptions lenient{1e-6, 10.0};
    const auto a = certify_frictional(pair, kBox, kD, 0.5, lenient, from_0);
    const auto b = certify_frictional(pair, kBox, kD, 0.5, lenient, from_1);
    BOOST_TEST_REQUIRE(a.by_witness);
    BOOST_TEST_REQUIRE(a.residual.size() == 2u);
    BOOST_TEST(a.residual == b.residual, boost::test_tools::per_element());
    // The pair force is not balanced by anything: each sphere keeps it, √(0.2² + 0.02² + 0.03²)
    // in force plus the friction's torque over d (lever r = d/2: |r·f_t|/d = 0.5·|f_t|).
    const double force = std::sqrt(0.2 * 0.2 + 0.02 * 0.02 + 0.03 * 0.03);
    const double torque = 0.5 * std::sqrt(0.02 * 0.02 + 0.03 * 0.03);
    BOOST_TEST(a.residual[0] == std::hypot(force, torque), boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(an_overlap_deeper_than_the_tolerance_is_not_certified) {
    const double y0 = kBox.floor + 0.5 * kD;
    const auto c =
        certify_frictionless({sphere(0, y0, 0), sphere(0, y0 + 0.999 * kD, 0)}, kBox, kD);
    BOOST_TEST(c.residual_max <= 1e-12);  // balanced, but the spheres overlap by 1e-3 d
    BOOST_TEST(!c.certified);
    BOOST_TEST(c.overlap_max_over_d == 1e-3, boost::test_tools::tolerance(1e-9));
}

// A settled frictionless DEM pour (μ = 0; its contacts overlap by up to ~5·10⁻³ d) is in
// balance on the normal forces of its overlapping pairs. Measured: largest residual
// 0.025 m·g (4 spheres above 0.01, still creeping when the pour stopped), 0.066 m·g over
// all 1002 with the solver run to its end; it stops sooner while a residual is 10× its
// target (0.034 and 0.21 m·g then), so the bounds are 0.05 and 3·10⁻⁴ of the weight. A frictional
// pour (μ = 0.5) leans on friction: most of its weight is out of frictionless balance (894 of 1002
// m·g).
BOOST_AUTO_TEST_CASE(a_settled_frictionless_pour_is_balanced) {
    const Pack pack =
        read_pack_file(std::string(SGMP_SOURCE_DIR) + "/data/reference/n1002-mu0-seed1.xyz.gz");
    const double d = 2.0 * pack.particles.front().radius;
    CertificateOptions options;
    options.gap_tolerance_over_d = 0.0;  // the overlapping and touching pairs only
    const auto began = std::chrono::steady_clock::now();
    const auto c = certify_frictionless(pack.particles, Container{}, d, options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    BOOST_TEST_MESSAGE("mu = 0 pour, N = 1002: largest residual "
                       << c.residual_max << " m g, " << c.contacts << " contacts, " << seconds
                       << " s");
    BOOST_TEST(c.residual_max <= 0.05);
    BOOST_TEST(c.residual_sum <= 3e-4 * c.weight_sum);
    BOOST_TEST(!c.certified);  // it overlaps
    const Pack frictional =
        read_pack_file(std::string(SGMP_SOURCE_DIR) + "/data/reference/n1002-mu0.5-seed1.xyz.gz");
    const auto f = certify_frictionless(frictional.particles, Container{}, d, options);
    BOOST_TEST(f.residual_sum >= 0.5 * f.weight_sum);
}

BOOST_AUTO_TEST_SUITE_END()
