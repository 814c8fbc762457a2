// The hard-sphere settling (hard_sphere_settle.hpp): closed-form cases, and relaxed packs
// that end as certified equilibria (checked by the certificate, whose LP is independent of
// the settling's: it sees only the final positions).
#include <algorithm>
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "sgmp/engine/equilibrium_certificate.hpp"
#include "sgmp/engine/hard_sphere_settle.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/pack/pack_overlaps.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

const Container kBox{};
constexpr double kD = 0.1;

Particle sphere(double x, double y, double z) {
    return Particle{0, Vec3(x, y, z), 0.5 * kD, 0};
}

/// A loose-random pack relaxed by `--relax frictionless` (or frictional at μ; the
/// frictional settling takes about a minute at N = 150, so its tests pack fewer).
Pack relaxed_pack(std::uint64_t seed, RelaxMode mode = RelaxMode::Frictionless,
                  double friction = 0.5, std::size_t count = 150) {
    PackRequest request;
    request.count = count;
    request.arrangement = Arrangement::LooseRandom;
    request.seed = seed;
    request.relax.mode = mode;
    request.relax.friction = friction;
    return make_pack(request);
}

/// Three spheres touching each other on the floor (centres at distance d/√3 from the
/// axis x = z = 0) and a fourth resting on all three: a close-packed tetrahedron.
std::vector<Particle> tetrahedron_on_the_floor() {
    const double y0 = kBox.floor + 0.5 * kD;
    const double spread = kD / std::sqrt(3.0);
    std::vector<Particle> p;
    for (int k = 0; k < 3; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 3.0;
        p.push_back(sphere(spread * std::cos(a), y0, spread * std::sin(a)));
    }
    p.push_back(sphere(0, y0 + std::sqrt(kD * kD - spread * spread), 0));
    return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(hard_sphere_settle)

BOOST_AUTO_TEST_CASE(a_floating_column_falls_onto_the_floor) {
    // Three spheres stacked with gaps of 0.3·d, 0.2·d, 0.1·d: they end touching, the lowest
    // on the floor (exactly: the floor is a bound of the LP, the pairs its rows), still one
    // above the other (the column may slide sideways as a whole: a move of no energy).
    std::vector<Particle> p{sphere(0, kBox.floor + 0.8 * kD, 0),
                            sphere(0, kBox.floor + 2.0 * kD, 0),
                            sphere(0, kBox.floor + 3.1 * kD, 0)};
    const SettleStats s = settle_hard_spheres(p, kBox, kD);
    BOOST_TEST(s.converged);
    for (int k = 0; k < 3; ++k) {
        // Rounding of a few operations on coordinates of order 1: 1e-12.
        BOOST_TEST(p[k].center.y() == kBox.floor + (0.5 + k) * kD,
                   boost::test_tools::tolerance(1e-12));
        BOOST_TEST(std::abs(p[k].center.x() - p[0].center.x()) <= 1e-12);
        BOOST_TEST(std::abs(p[k].center.z() - p[0].center.z()) <= 1e-12);
    }
    // Energy released: (0.3) + (0.3 + 0.2) + (0.3 + 0.2 + 0.1) = 1.4 weights·d.
    BOOST_TEST(s.energy_drop == 1.4, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(certify_frictionless(p, kBox, kD).certified);
    // The LP's multipliers are the contact forces: floor 3, pairs 2 and 1 (closed form),
    // and they certify on their own (no certificate LP).
    const auto witness = certify_frictionless(p, kBox, kD, {}, s.forces);
    BOOST_TEST(witness.by_witness);
    BOOST_TEST(witness.residual_max <= 1e-9);
    BOOST_TEST_REQUIRE(witness.force.size() == 3u);
    double total = 0.0;
    for (const double f : witness.force) {
        total += f;
    }
    BOOST_TEST(total == 6.0, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(a_sphere_on_a_single_sphere_slides_off_into_a_pocket) {
    // A sphere resting slightly off the top of another on the floor is not in balance; it
    // slides off and down until three contacts (the sphere below, the floor, a wall or
    // others) hold it. Near a corner the pocket is floor + wall + wall or the sphere.
    const double y0 = kBox.floor + 0.5 * kD;
    std::vector<Particle> p{sphere(kBox.x_min + 0.5 * kD, y0, kBox.z_min + 0.5 * kD),
                            sphere(kBox.x_min + 0.5 * kD + 0.01 * kD, y0 + kD + 0.001,
                                   kBox.z_min + 0.5 * kD + 0.01 * kD)};
    const double before = p[1].center.y();
    const SettleStats s = settle_hard_spheres(p, kBox, kD);
    BOOST_TEST(s.converged);
    BOOST_TEST(p[1].center.y() < before);
    const auto c = certify_frictionless(p, kBox, kD);
    BOOST_TEST(c.certified, "residual " << c.residual_max);
    BOOST_TEST(c.overlap_max_over_d <= 1e-12);
    const auto witness = certify_frictionless(p, kBox, kD, {}, s.forces);
    BOOST_TEST(witness.by_witness, "witness residual " << witness.residual_max);
}

BOOST_AUTO_TEST_CASE(a_tetrahedron_stands_with_enough_friction_and_collapses_without) {
    // Closed form (friction_test.cpp, tripod_threshold, with no spread): a lower sphere
    // carries its weight through its centre, the floor's force at its lowest point B and
    // the upper sphere's at the contact C; three forces in balance meet in a point, so the
    // upper sphere's force runs along C→B, at θ/2 from the normal at C, θ the angle of C
    // from the vertical: sin θ = 1/√3, θ = 35.26°. The tetrahedron stands for
    // μ ≥ tan(θ/2) = 0.318 (for the LP's inscribed pyramid, μ·cos(π/8) ≥ 0.318 is enough
    // whatever its orientation: μ ≥ 0.344), and no frictionless forces hold it (the
    // lower spheres touch each other, which cannot keep them from spreading).
    std::vector<Particle> p = tetrahedron_on_the_floor();
    BOOST_TEST(!certify_frictionless(p, kBox, kD).certified);
    BOOST_TEST(certify_frictional(p, kBox, kD, 0.5).certified);
    BOOST_TEST(!certify_frictional(p, kBox, kD, 0.25).certified);
    SettleOptions stick;
    stick.friction = 0.5;
    const SettleStats held = settle_hard_spheres(p, kBox, kD, stick);
    BOOST_TEST(held.converged);
    // It stands: nothing to release, and nothing moves beyond the LP's tolerances (10⁻¹⁰
    // of the trust region per step, moves of 4·10⁻¹² d measured over all steps).
    BOOST_TEST(held.energy_drop <= 1e-12);
    BOOST_TEST(held.move_max <= 1e-10);
    // At μ = 0.2 the lower spheres roll and slide apart and the upper one comes down into
    // a frictional equilibrium at 0.2.
    SettleOptions slip;
    slip.friction = 0.2;
    const double before = p[3].center.y();
    const SettleStats fell = settle_hard_spheres(p, kBox, kD, slip);
    BOOST_TEST(fell.converged);
    BOOST_TEST(p[3].center.y() < before - 1e-3 * kD);
    const auto c = certify_frictional(p, kBox, kD, 0.2);
    BOOST_TEST(c.certified, "residual " << c.residual_max);
    BOOST_TEST(c.overlap_max_over_d <= 1e-12);
}

BOOST_AUTO_TEST_CASE(a_sphere_on_two_is_an_equilibrium_that_the_settling_keeps) {
    // Two spheres touching on the floor and a third on both, centres in one vertical
    // plane: an equilibrium at μ ≥ 2 − √3 = 0.268 (the upper contacts carry N = w/2 and a
    // tangential (2 − √3)/2·w; checked by HiGHS in tests/python/test_certificate.py), but
    // not a stable one: the upper sphere can roll without slipping about the axis through
    // its two contacts, which costs no energy at first order and lowers its centre at
    // second. The settling looks for first-order equilibria: moves cost 10⁻⁶ m·g per unit,
    // so it takes no move that lowers nothing at first order and keeps the triangle.
    const double y0 = kBox.floor + 0.5 * kD;
    std::vector<Particle> p{sphere(-0.5 * kD, y0, 0), sphere(0.5 * kD, y0, 0),
                            sphere(0, y0 + std::sqrt(3.0) / 2.0 * kD, 0)};
    BOOST_TEST(certify_frictional(p, kBox, kD, 0.5).certified);
    BOOST_TEST(!certify_frictional(p, kBox, kD, 0.2).certified);
    SettleOptions options;
    options.friction = 0.5;
    const SettleStats s = settle_hard_spheres(p, kBox, kD, options);
    BOOST_TEST(s.converged);
    BOOST_TEST(s.energy_drop <= 1e-12);
    BOOST_TEST(certify_frictional(p, kBox, kD, 0.5).certified);
}

BOOST_AUTO_TEST_CASE(frictional_relaxed_packs_are_certified_equilibria_over_seeds) {
    // `--relax frictional` ends in a certified frictional equilibrium at its own μ: force
    // and torque of every sphere balanced to 10⁻³ m·g by forces inside the Coulomb
    // pyramids at gaps ≤ 10⁻⁶·d, no overlap.
    for (const unsigned seed : {1u, 2u}) {
        for (const double mu : {0.2, 0.5}) {
            const Pack pack = relaxed_pack(seed, RelaxMode::Frictional, mu, 60);
            BOOST_TEST(pack.metadata.get("certified").value_or("") == "true",
                       "seed " << seed << " mu " << mu << ": residual "
                               << pack.metadata.get("certificate_residual_max").value_or(""));
            BOOST_TEST(pack.metadata.get("certificate").value_or("") == "frictional");
            const std::string end = pack.metadata.get("relax_settle_end").value_or("");
            BOOST_TEST((end == "still" || end == "trust-region"), end);
            const auto overlaps = count_overlaps(pack.particles, kBox, 1e-12 * kD);
            BOOST_TEST(overlaps.pairs == 0u);
            BOOST_TEST(overlaps.walls == 0u);
        }
    }
}

BOOST_AUTO_TEST_CASE(relaxed_packs_are_certified_equilibria_over_seeds) {
    // `--relax frictionless` ends in a certified equilibrium: every weight balanced to
    // 10⁻³ m·g by non-negative forces at gaps ≤ 10⁻⁶·d, no overlap, every sphere inside.
    for (const unsigned seed : {1u, 2u, 3u, 4u}) {
        const Pack pack = relaxed_pack(seed);
        BOOST_TEST(pack.metadata.get("certified").value_or("") == "true",
                   "seed " << seed << ": residual "
                           << pack.metadata.get("certificate_residual_max").value_or(""));
        BOOST_TEST(pack.metadata.get("relax_settle_converged").value_or("") == "true");
        const auto overlaps = count_overlaps(pack.particles, kBox, 1e-12 * kD);
        BOOST_TEST(overlaps.pairs == 0u);
        BOOST_TEST(overlaps.walls == 0u);
    }
}

BOOST_AUTO_TEST_CASE(the_same_pack_settles_to_the_same_bytes) {
    const Pack a = relaxed_pack(7);
    const Pack b = relaxed_pack(7);
    BOOST_TEST_REQUIRE(a.particles.size() == b.particles.size());
    for (std::size_t i = 0; i < a.particles.size(); ++i) {
        BOOST_TEST((a.particles[i].center == b.particles[i].center));
    }
}

BOOST_AUTO_TEST_CASE(progress_follows_every_phase_and_changes_nothing) {
    PackRequest request;
    request.count = 150;
    request.arrangement = Arrangement::LooseRandom;
    request.seed = 7;
    request.relax.mode = RelaxMode::Frictionless;
    std::vector<RelaxProgress> seen;
    const Pack with =
        make_pack(request, {}, nullptr, [&](const RelaxProgress& p) { seen.push_back(p); });
    const Pack without = relaxed_pack(7);
    for (std::size_t i = 0; i < with.particles.size(); ++i) {
        BOOST_TEST((with.particles[i].center == without.particles[i].center));
    }
    BOOST_TEST_REQUIRE(!seen.empty());
    // Phases in order (soft, clearing, settling), steps and LP iterations never go back,
    // and the last call is the settling's last LP.
    for (std::size_t k = 1; k < seen.size(); ++k) {
        BOOST_TEST(static_cast<int>(seen[k].phase) >= static_cast<int>(seen[k - 1].phase));
        BOOST_TEST(seen[k].steps >= seen[k - 1].steps);
        BOOST_TEST(seen[k].settle_iteration >= seen[k - 1].settle_iteration);
    }
    BOOST_TEST((seen.back().phase == RelaxProgress::Phase::Settling));
    BOOST_TEST(seen.back().settle_iteration ==
               std::stoi(*with.metadata.get("relax_settle_iterations")));
    BOOST_TEST(std::count_if(seen.begin(), seen.end(), [](const RelaxProgress& p) {
                   return p.phase == RelaxProgress::Phase::Clearing;
               }) == 1);
}

BOOST_AUTO_TEST_SUITE_END()
