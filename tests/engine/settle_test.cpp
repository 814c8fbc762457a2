// The hard-sphere settling (hard_sphere_settle.hpp): closed-form cases, and relaxed packs
// that end as certified equilibria (checked by the certificate, whose LP is independent of
// the settling's: it sees only the final positions).
#include <algorithm>
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>

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

/// A loose-random pack of 150 relaxed by `--relax frictionless`.
Pack relaxed_pack(std::uint64_t seed) {
    PackRequest request;
    request.count = 150;
    request.arrangement = Arrangement::LooseRandom;
    request.seed = seed;
    request.relax.mode = RelaxMode::Frictionless;
    return make_pack(request);
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
