// The frictional relaxation (`--relax frictional`): a tripod that friction holds and that
// collapses below the analytic friction threshold, μ = 0 reproducing the frictionless
// relaxation bit for bit, the pack invariants over many packs, determinism and the header.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "brute_force.hpp"
#include "pack_invariants.hpp"
#include "refusal.hpp"
#include "sgmp/engine/equilibrium_certificate.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/engine/pack_checks.hpp"
#include "sgmp/engine/relax.hpp"
#include "test_support.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

using sgmp::testing::sphere;

RelaxParams frictional(double mu) {
    RelaxParams params;
    params.mode = RelaxMode::Frictional;
    params.friction = mu;
    params.shell = 0.0;
    return params;
}

/// Three spheres on the floor at the corners of an equilateral triangle, 10 % of d apart,
/// and a fourth resting on all three (touching each). Returns the top sphere's height.
std::vector<Particle> tripod(double r, double& top) {
    const Container box;
    const double d = 2.0 * r;
    const double y0 = box.floor + r;
    const double R = 1.1 * d / std::sqrt(3.0);  // circumradius of the spread triangle
    std::vector<Particle> ps;
    for (int k = 0; k < 3; ++k) {
        const double a = 2.0 * M_PI * k / 3.0;
        ps.push_back(sphere(k + 1, R * std::cos(a), y0, R * std::sin(a), r));
    }
    top = y0 + std::sqrt(d * d - R * R);
    ps.push_back(sphere(4, 0.0, top, 0.0, r));
    return ps;
}

/// The friction a base sphere of the tripod needs. It carries three forces: its weight
/// (through its centre O), the floor's at its lowest point B and the top sphere's at the
/// contact C. Three forces in equilibrium meet in a point; the weight's line runs through
/// B, so the top sphere's force runs along C→B. With θ the angle of C from the vertical
/// at O, the chord CB makes the angle θ/2 with the normal at C and with the vertical at B:
/// both contacts need μ ≥ tan(θ/2).
double tripod_threshold(double r) {
    const double d = 2.0 * r;
    const double R = 1.1 * d / std::sqrt(3.0);
    const double theta = std::atan2(R, std::sqrt(d * d - R * R));  // C from the vertical
    return std::tan(0.5 * theta);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(friction)

BOOST_AUTO_TEST_CASE(friction_holds_a_spread_tripod_above_its_threshold_and_not_below) {
    // Above the threshold the tripod stands: the relaxation ends in a certified frictional
    // equilibrium at μ with the top sphere where it was, up to the soft stages' overlaps
    // squeezed out and the contacts closed by the settling (measured 1.7·10⁻⁴·d at μ = 0.6
    // and 1.0; bound 10⁻³·d). The base spheres, on two contacts each, could roll about the
    // chord through them at no first-order cost; the settling takes no such move (each
    // move costs 10⁻⁶ of a weight per unit). Below the threshold the top sphere falls.
    const Container box;
    const double r = 0.05;
    const double d = 2.0 * r;
    const double threshold = tripod_threshold(r);  // 0.358 for a 10 % spread
    BOOST_TEST_REQUIRE(threshold > 0.35);
    BOOST_TEST_REQUIRE(threshold < 0.37);
    for (const double mu : {0.0, 0.2, 0.3, 0.6, 1.0}) {
        double top = 0.0;
        std::vector<Particle> ps = tripod(r, top);
        relax_pack(ps, box, frictional(mu), d);
        BOOST_TEST_INFO("mu " << mu << " (threshold " << threshold << "), top "
                              << (ps[3].center.y() - top) / d << " d from its start");
        BOOST_TEST(certify_frictional(ps, box, d, mu).certified);
        if (mu > threshold) {
            // Held on its supports.
            BOOST_TEST(std::abs(ps[3].center.y() - top) <= 1e-3 * d);
        } else {
            // Collapsed: the base slides apart and the top sphere falls, by at least 0.3·d
            // (it ends on the floor, d/2 above its bottom neighbours' centres at most).
            BOOST_TEST(ps[3].center.y() <= top - 0.3 * d);
        }
        BOOST_TEST(engine::testing::worst_pair_gap(ps) >= -1e-9 * d);
        BOOST_TEST(engine::testing::worst_penetration(ps, box) <= 1e-9 * d);
    }
}

BOOST_AUTO_TEST_CASE(without_friction_the_frictional_relaxation_is_the_frictionless_one) {
    // With μ = 0 every tangential force is capped at zero, and the rolling degrees of
    // freedom feel no torque: the same FIRE trajectory, and at μ = 0 the frictional
    // settling is the frictionless one, so the same bits — given the same stiffness
    // schedule (each mode has its own defaults: relax_schedule).
    PackRequest request;
    request.count = 500;
    request.arrangement = Arrangement::LooseRandom;
    request.seed = 3;
    request.relax.mode = RelaxMode::Frictionless;
    request.relax.stiffness = 2e3;
    request.relax.stages = 5;
    request.relax.time = 5.0;
    const Pack frictionless = make_pack(request);
    request.relax.mode = RelaxMode::Frictional;
    request.relax.friction = 0.0;
    const Pack zero = make_pack(request);
    BOOST_TEST_REQUIRE(frictionless.particles.size() == zero.particles.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < zero.particles.size(); ++i) {
        differ += zero.particles[i].center == frictionless.particles[i].center ? 0 : 1;
    }
    BOOST_TEST(differ == 0u);
}

BOOST_AUTO_TEST_CASE(friction_keeps_the_pack_looser_than_the_frictionless_relaxation) {
    // From the same deposited pack, friction stops the collective sliding early: a higher
    // gravitational energy (Σ rᵢ³·yᵢ) than without friction, and lower than before.
    PackRequest request;
    request.count = 60;  // the frictional settling takes minutes at 150 (engine docs)
    request.arrangement = Arrangement::LooseRandom;
    const auto energy = [](const Pack& pack) {
        double e = 0.0;
        for (const Particle& p : pack.particles) {
            e += p.radius * p.radius * p.radius * p.center.y();
        }
        return e;
    };
    const double deposited = energy(make_pack(request));
    request.relax.mode = RelaxMode::Frictionless;
    const double frictionless = energy(make_pack(request));
    request.relax.mode = RelaxMode::Frictional;
    const double frictional = energy(make_pack(request));
    BOOST_TEST_INFO("deposited " << deposited << ", frictional " << frictional << ", frictionless "
                                 << frictionless);
    BOOST_TEST(frictional < deposited);
    BOOST_TEST(frictional > frictionless);
}

BOOST_AUTO_TEST_CASE(frictional_packs_keep_the_invariants_over_seeds_and_arrangements) {
    int packs = 0;
    for (const Arrangement a : {Arrangement::SingleColumn, Arrangement::SmallDense,
                                Arrangement::LargeDense, Arrangement::LooseRandom}) {
        for (const std::size_t count : {20u, 40u}) {  // the frictional settling is slow
            for (const std::uint64_t seed : {1u, 2u}) {
                PackRequest request;
                request.count = count;
                request.arrangement = a;
                request.seed = seed;
                request.relax.mode = RelaxMode::Frictional;
                if (seed == 2) {
                    request.size_modes = {{1.0, 0.7}, {0.5, 0.3}};
                }
                const Pack pack = make_pack(request);
                const double d = *pack.metadata.get_number("diameter");
                BOOST_TEST_INFO(to_string(a) << " N " << count << " seed " << seed);
                BOOST_TEST_REQUIRE(pack.particles.size() == count);
                engine::testing::check_no_overlap_and_inside(pack.particles, d);
                ++packs;
            }
        }
    }
    BOOST_TEST(packs == 16);
}

BOOST_AUTO_TEST_CASE(same_frictional_request_gives_the_same_bytes_and_header) {
    PackRequest request;
    request.count = 30;
    request.arrangement = Arrangement::LooseRandom;
    request.seed = 5;
    request.relax.mode = RelaxMode::Frictional;
    request.relax.friction = 0.7;
    const Pack first = make_pack(request);
    const Pack second = make_pack(request);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < first.particles.size(); ++i) {
        differ += first.particles[i].center == second.particles[i].center ? 0 : 1;
    }
    BOOST_TEST(differ == 0u);
    BOOST_TEST((first.metadata.entries() == second.metadata.entries()));
    const Metadata& m = first.metadata;
    BOOST_TEST(m.get("relax").value_or("") == "frictional");
    BOOST_TEST(m.get_number("relax_friction").value_or(0) == 0.7);
    BOOST_TEST(m.get_number("relax_tangential_ratio").value_or(0) == 2.0 / 7.0);
}

BOOST_AUTO_TEST_CASE(bad_friction_parameters_are_refused_with_the_option_named) {
    PackRequest request;
    request.count = 100;
    request.relax.mode = RelaxMode::Frictional;
    request.relax.friction = -0.1;
    BOOST_TEST(refusal([&] { validate(request); }).find("--relax-friction -0.1: must be in") == 0u);
    request.relax.friction = 0.5;
    request.relax.tangential_ratio = 0.0;
    BOOST_TEST(refusal([&] { validate(request); }).find("--relax-tangential-ratio 0: must be") ==
               0u);
    request.relax.tangential_ratio = 0.4;
    BOOST_TEST(refusal([&] { validate(request); }).empty());
}

BOOST_AUTO_TEST_SUITE_END()
