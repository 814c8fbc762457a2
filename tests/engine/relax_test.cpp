// The relaxation (`--relax frictionless`): hand-made beds with known equilibria, the
// hard-sphere finish on a known pocket, the pack invariants over many packs, the fall in
// gravitational energy, the clearing of a relaxation cut short, determinism and
// `--relax none`.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "brute_force.hpp"
#include "pack_invariants.hpp"
#include "refusal.hpp"
#include "sgmp/engine/hard_sphere_finish.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/engine/pack_checks.hpp"
#include "sgmp/engine/relax.hpp"
#include "test_support.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

using sgmp::testing::sphere;

RelaxParams frictionless(double shell) {
    RelaxParams params;
    params.mode = RelaxMode::Frictionless;
    params.shell = shell;
    return params;
}

/// Σ wᵢ·yᵢ with wᵢ ∝ rᵢ³: the gravitational energy up to a constant factor.
double potential_energy(const std::vector<Particle>& ps) {
    double e = 0.0;
    for (const Particle& p : ps) {
        e += p.radius * p.radius * p.radius * p.center.y();
    }
    return e;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(relax)

BOOST_AUTO_TEST_CASE(one_sphere_comes_to_rest_on_the_floor) {
    const Container box;
    const double d = 0.1;
    const double r = 0.5 * d;
    for (const double shell : {0.0, 3e-4}) {
        std::vector<Particle> ps = {sphere(1, 0.1, 0.2, -0.1, r)};
        const RelaxParams params = frictionless(shell);
        const RelaxStats stats = relax_pack(ps, box, params, d);
        BOOST_TEST_INFO("shell " << shell);
        BOOST_TEST(stats.stages_converged == relax_schedule(params).stages);
        // The hard-sphere settling ends it exactly on the floor (the floor is a bound of its
        // LP): rounding of a few operations on coordinates of order 1, 1e-12.
        BOOST_TEST(std::abs(ps[0].center.y() - (box.floor + r)) <= 1e-12);
        // Frictionless floor: nothing pushes sideways.
        BOOST_TEST(ps[0].center.x() == 0.1);
        BOOST_TEST(ps[0].center.z() == -0.1);
    }
}

BOOST_AUTO_TEST_CASE(two_spheres_wedge_between_the_walls_at_the_analytic_height) {
    // Two spheres of radius 0.35 in the 1.25-wide container cannot lie side by side
    // (4r > 1.25): the lower one is pushed into the corner of the floor and wall x_max, the
    // upper one against wall x_min, resting on the lower one. Its height follows from the
    // contact: Δx = 1.25 − 2r = 0.55 between the centres, Δy = √((2r)² − Δx²).
    const Container box;
    const double r = 0.35;
    const double d = 2.0 * r;
    std::vector<Particle> ps = {sphere(1, 0.2, -0.2, 0.0, r), sphere(2, -0.2, 0.4, 0.0, r)};
    const RelaxParams params = frictionless(0.0);
    const RelaxStats stats = relax_pack(ps, box, params, d);
    BOOST_TEST(stats.stages_converged == relax_schedule(params).stages);
    const double dx = box.x_max - box.x_min - 2.0 * r;
    const double upper = box.floor + r + std::sqrt(d * d - dx * dx);
    // The soft overlaps (≈ 2 m·g/k_last ≈ 1e-6·d) are parted by the clearing (FIRE without
    // gravity), whose inertia leaves the spheres a little past touching: measured 3.1e-9·d;
    // 1e-8·d is 1 % of the overlaps it parts.
    const double tolerance = 1e-8 * d;
    BOOST_TEST(std::abs(ps[0].center.x() - (box.x_max - r)) <= tolerance);
    BOOST_TEST(std::abs(ps[0].center.y() - (box.floor + r)) <= tolerance);
    BOOST_TEST(std::abs(ps[1].center.x() - (box.x_min + r)) <= tolerance);
    BOOST_TEST(std::abs(ps[1].center.y() - upper) <= tolerance);
    // Along z nothing holds them (frictionless walls): a move of no energy, which the
    // settling may take; they stay level with each other.
    BOOST_TEST(std::abs(ps[0].center.z() - ps[1].center.z()) <= tolerance);
}

BOOST_AUTO_TEST_CASE(a_sphere_settles_into_the_pocket_of_four_corner_spheres) {
    // Four spheres of radius 0.3 in the four corners of the floor (each held by two walls,
    // 0.05 apart from each other) and a fifth dropped off-centre above them: it slides into
    // the pocket, centred, at the height where it touches all four:
    // horizontal distance h = √2·(0.625 − r), y = floor + r + √((2r)² − h²).
    const Container box;
    const double r = 0.3;
    const double d = 2.0 * r;
    const double c = 0.625 - r;
    std::vector<Particle> ps = {sphere(1, -c, -c, -c, r), sphere(2, c, -c, -c, r),
                                sphere(3, -c, -c, c, r), sphere(4, c, -c, c, r),
                                sphere(5, 0.03, 0.3, -0.02, r)};
    const RelaxParams params = frictionless(0.0);
    const RelaxStats stats = relax_pack(ps, box, params, d);
    BOOST_TEST(stats.stages_converged == relax_schedule(params).stages);
    const double h = std::sqrt(2.0) * c;
    const double top = box.floor + r + std::sqrt(d * d - h * h);
    // Centred: the residual force (≤ 1e-4 m·g) on the top sphere displaces it sideways by
    // about 1e-4·d/k_last per contact, far below 1e-9·d. Its four loaded contacts (≈ 1e-6·d
    // deep) are parted by the clearing, without gravity: the bottom spheres rebound off the
    // floor by up to 6e-8·d (measured) before FIRE stops them, so heights hold to 1e-7·d.
    const double tolerance = 1e-7 * d;
    BOOST_TEST(std::abs(ps[4].center.x()) <= tolerance);
    BOOST_TEST(std::abs(ps[4].center.z()) <= tolerance);
    BOOST_TEST(std::abs(ps[4].center.y() - top) <= tolerance);
    for (int i = 0; i < 4; ++i) {
        BOOST_TEST(std::abs(ps[i].center.y() - (box.floor + r)) <= tolerance);
        BOOST_TEST(std::abs(std::abs(ps[i].center.x()) - c) <= tolerance);
    }
}

BOOST_AUTO_TEST_CASE(the_finish_pushes_a_sunk_sphere_out_onto_three_touching_spheres) {
    // Three touching spheres on the floor (an equilateral triangle of side 2r) and a fourth
    // sunk 1e-4·d into their pocket: the finish pushes it out to where it touches all three,
    // the apex of a regular tetrahedron of edge 2r: 2r·√(2/3) above the others' centres.
    const Container box;
    const double r = 0.05;
    const double d = 2.0 * r;
    const double y0 = box.floor + r;
    const double apex = y0 + d * std::sqrt(2.0 / 3.0);
    // Triangle centred on (0.1, 0.2) in x, z; circumradius 2r/√3.
    const double R = d / std::sqrt(3.0);
    std::vector<Particle> ps;
    for (int k = 0; k < 3; ++k) {
        const double a = 2.0 * M_PI * k / 3.0;
        ps.push_back(sphere(k + 1, 0.1 + R * std::cos(a), y0, 0.2 + R * std::sin(a), r));
    }
    ps.push_back(sphere(4, 0.1, apex - 1e-4 * d, 0.2, r));
    const FinishStats stats = finish_as_hard_spheres(ps, box, 1e-10 * d);
    BOOST_TEST(stats.lifted == 0u);  // the pushes alone place it, no vertical lift
    for (int k = 0; k < 3; ++k) {
        BOOST_TEST(ps[k].center.y() == y0);  // already apart: not moved
    }
    // No overlap deeper than the finish's 1e-10·d (plus rounding).
    BOOST_TEST(engine::testing::worst_pair_gap(ps) >= -1e-10 * d - 1e-15);
    // Free of the three, it cannot sit lower than the apex (1e-9·d: the overlap allowed
    // plus rounding). The pushes go along the contact normals until no overlap is left, so
    // it may end on one of the three slightly above the apex: by at most the overlap it
    // started with (1e-4·d), never by the √(2r·δ) ≈ 0.01·d of a vertical lift.
    BOOST_TEST(ps[3].center.y() >= apex - 1e-9 * d);
    BOOST_TEST(ps[3].center.y() <= apex + 1e-4 * d);
    BOOST_TEST(std::hypot(ps[3].center.x() - 0.1, ps[3].center.z() - 0.2) <= 1e-4 * d);
    BOOST_TEST(stats.move_max <= 2e-4 * d);
    // Touching (gap ≤ 1e-9·d) at least the one it was last pushed from: still supported.
    int touching = 0;
    for (int k = 0; k < 3; ++k) {
        touching += surface_gap(ps[3], ps[k]) <= 1e-9 * d ? 1 : 0;
    }
    BOOST_TEST(touching >= 1);
}

BOOST_AUTO_TEST_CASE(relaxed_packs_keep_the_invariants_over_seeds_arrangements_and_sizes) {
    int packs = 0;
    for (const Arrangement a : {Arrangement::SingleColumn, Arrangement::SmallDense,
                                Arrangement::LargeDense, Arrangement::LooseRandom}) {
        for (const std::size_t count : {40u, 150u, 400u}) {
            for (const std::uint64_t seed : {1u, 2u}) {
                for (const bool bimodal : {false, true}) {
                    PackRequest request;
                    request.count = count;
                    request.arrangement = a;
                    request.seed = seed;
                    request.relax.mode = RelaxMode::Frictionless;
                    if (bimodal) {
                        request.size_modes = {{1.0, 0.7}, {0.5, 0.3}};
                        request.protocol.contact = ContactModel::Roll;
                    }
                    const Pack pack = make_pack(request);
                    const double d = *pack.metadata.get_number("diameter");
                    BOOST_TEST_INFO(to_string(a) << " N " << count << " seed " << seed
                                                 << (bimodal ? " bimodal" : ""));
                    BOOST_TEST_REQUIRE(pack.particles.size() == count);
                    engine::testing::check_no_overlap_and_inside(pack.particles, d);
                    ++packs;
                }
            }
        }
    }
    BOOST_TEST(packs == 48);
}

BOOST_AUTO_TEST_CASE(relaxation_lowers_the_gravitational_energy) {
    for (const Arrangement a : {Arrangement::SingleColumn, Arrangement::SmallDense,
                                Arrangement::LargeDense, Arrangement::LooseRandom}) {
        PackRequest request;
        request.count = 300;
        request.arrangement = a;
        const double before = potential_energy(make_pack(request).particles);
        request.relax.mode = RelaxMode::Frictionless;
        const double after = potential_energy(make_pack(request).particles);
        BOOST_TEST_INFO(to_string(a) << ": before " << before << ", after " << after);
        BOOST_TEST(after < before);
    }
}

BOOST_AUTO_TEST_CASE(a_relaxation_cut_short_leaves_the_finish_nothing_to_lift) {
    // One soft stage (k = 2·10⁴ m·g/d) cut short at 0.5·√(H/g), with a shell (10⁻⁵) thinner
    // than its loaded overlaps (up to 3·10⁻³·d): the pack ends still sliding, its real spheres
    // overlapping. The clearing parts them before the finish, which then has nothing to lift
    // (without it the finish lifted 112–135 spheres of these packs by up to 3·d). What the
    // finish may still move is its own tolerance, 10⁻¹⁰·d, plus rounding: 10⁻⁹·d.
    for (const std::uint64_t seed : {1, 2, 3}) {
        PackRequest request;
        request.count = 1000;
        request.arrangement = Arrangement::LooseRandom;
        request.seed = seed;
        request.relax.mode = RelaxMode::Frictionless;
        request.relax.stages = 1;
        request.relax.stiffness = 2e4;
        request.relax.time = 0.5;
        request.relax.shell = 1e-5;
        const Pack pack = make_pack(request);
        const Metadata& m = pack.metadata;
        BOOST_TEST_INFO("seed " << seed);
        BOOST_TEST(m.get_number("relax_stages_converged").value_or(-1) == 0.0);
        BOOST_TEST(m.get_number("relax_finish_lifted").value_or(-1) == 0.0);
        BOOST_TEST(m.get_number("relax_finish_move_max").value_or(1) <= 1e-9);
        const double d = *m.get_number("diameter");
        BOOST_TEST(engine::testing::worst_pair_gap(pack.particles) >= -1e-9 * d);
    }
}

BOOST_AUTO_TEST_CASE(same_request_gives_the_same_relaxed_pack_bit_for_bit) {
    PackRequest request;
    request.count = 600;
    request.arrangement = Arrangement::LooseRandom;
    request.seed = 7;
    request.relax.mode = RelaxMode::Frictionless;
    const Pack first = make_pack(request);
    const Pack second = make_pack(request);
    BOOST_TEST_REQUIRE(first.particles.size() == second.particles.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < first.particles.size(); ++i) {
        differ += first.particles[i].center == second.particles[i].center ? 0 : 1;
    }
    BOOST_TEST(differ == 0u);
    BOOST_TEST((first.metadata.entries() == second.metadata.entries()));
    request.relax.mode = RelaxMode::None;
    BOOST_TEST((make_pack(request).particles[300].center != first.particles[300].center));
}

BOOST_AUTO_TEST_CASE(relax_none_changes_nothing_and_records_nothing) {
    PackRequest plain;
    plain.count = 300;
    plain.arrangement = Arrangement::LargeDense;
    PackRequest none = plain;
    none.relax.mode = RelaxMode::None;
    none.relax.stiffness = 5e4;  // parameters of an unused relaxation change nothing either
    const Pack a = make_pack(plain);
    const Pack b = make_pack(none);
    BOOST_TEST((a.metadata.entries() == b.metadata.entries()));
    for (std::size_t i = 0; i < a.particles.size(); ++i) {
        BOOST_TEST((a.particles[i].center == b.particles[i].center));
    }
    for (const auto& [key, value] : a.metadata.entries()) {
        BOOST_TEST(key.rfind("relax", 0) != 0u);
    }
}

BOOST_AUTO_TEST_CASE(the_header_records_the_relaxation_and_what_it_did) {
    PackRequest request;
    request.count = 200;
    request.arrangement = Arrangement::LooseRandom;
    request.relax.mode = RelaxMode::Frictionless;
    request.relax.stiffness = 3e3;
    const Pack pack = make_pack(request);
    const Metadata& m = pack.metadata;
    BOOST_TEST(m.get("relax").value_or("") == "frictionless");
    BOOST_TEST(m.get_number("relax_stiffness").value_or(0) == 3e3);
    BOOST_TEST(m.get_number("relax_stiffness_factor").value_or(0) == 10.0);
    // The frictionless schedule's defaults for what was not set (relax_schedule).
    BOOST_TEST(m.get_number("relax_stages").value_or(0) == 1.0);
    BOOST_TEST(m.get_number("relax_shell").value_or(-1) == 0.0);
    BOOST_TEST(m.get_number("relax_force_tolerance").value_or(0) == 1e-4);
    BOOST_TEST(m.get_number("relax_time").value_or(0) == 200.0);
    BOOST_TEST(m.get_number("relax_crossings").value_or(0) == 40.0);
    BOOST_TEST(m.get_number("relax_steps").value_or(0) >= 4.0);
    for (const char* key :
         {"relax_stages_converged", "relax_force_max", "relax_overlap_max", "relax_finish_lifted",
          "relax_finish_move_max", "relax_finish_move_mean"}) {
        BOOST_TEST(m.contains(key), key);
    }
}

BOOST_AUTO_TEST_CASE(bad_relaxation_parameters_are_refused_with_the_option_named) {
    PackRequest request;
    request.count = 100;
    request.relax.mode = RelaxMode::Frictionless;
    request.relax.stiffness = 10.0;
    BOOST_TEST(refusal([&] { validate(request); }).find("--relax-stiffness 10: must be in") == 0u);
    request.relax.stiffness = 2e3;
    request.relax.stages = 0;
    BOOST_TEST(refusal([&] { validate(request); }).find("--relax-stages 0: must be 1 to 10") == 0u);
    request.relax.stages = 4;
    request.relax.force_tolerance = 0.0;
    BOOST_TEST(refusal([&] { validate(request); }).find("--relax-force-tolerance 0: must be") ==
               0u);
    request.relax.force_tolerance = 1e-4;
    request.relax.shell = -1.0;
    BOOST_TEST(refusal([&] { validate(request); }).find("--relax-shell -1: must be in") == 0u);
    request.relax.shell = 1e-4;
    BOOST_TEST(refusal([&] { validate(request); }).empty());
}

BOOST_AUTO_TEST_SUITE_END()
