// The three invariants of every pack, checked by brute force over many packs: no
// overlapping pair, every sphere inside the container, every sphere supported; and for the
// rolling contact model, every sphere at rest on the floor, a wall or three spheres.
#include <boost/test/unit_test.hpp>
#include <functional>

#include "brute_force.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/engine/pack_checks.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

struct Tally {
    int packs = 0;
};

/// Checks one pack; returns the number of particles checked.
void check_invariants(const PackRequest& request, Tally& tally) {
    const Pack pack = make_pack(request);
    const double d = *pack.metadata.get_number("diameter");
    const auto& ps = pack.particles;
    BOOST_TEST_INFO("count " << request.count << ", " << to_string(request.arrangement) << ", seed "
                             << request.seed << ", fall " << to_string(request.protocol.fall));
    BOOST_TEST_REQUIRE(ps.size() == request.count);
    // Tolerances: 1e-9·d absorbs rounding of contact positions (they are computed to
    // ~1e-16 relative); anything larger would be a real overlap or gap.
    const double tolerance = 1e-9 * d;
    BOOST_TEST(testing::worst_pair_gap(ps) >= -tolerance);
    BOOST_TEST(testing::worst_penetration(ps, Container{}) <= tolerance);
    // Exact fall: every sphere touches its support. Step fall: within one step of it.
    const double support_limit =
        request.protocol.fall == FallMode::Exact ? tolerance : request.protocol.fall_step;
    BOOST_TEST(testing::worst_support_distance(ps, Container{}) <= support_limit);
    // The engine's own O(N) check agrees with the brute force.
    const PackCheck check = check_pack(ps, Container{}, tolerance, support_limit);
    BOOST_TEST(check.overlaps == 0u);
    BOOST_TEST(check.outside == 0u);
    BOOST_TEST(check.unsupported == 0u);
    ++tally.packs;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(invariants)

BOOST_AUTO_TEST_CASE(thesis_protocol_packs_over_seeds_arrangements_counts_and_fall_modes) {
    Tally tally;
    for (const Arrangement a : {Arrangement::SingleColumn, Arrangement::SmallDense,
                                Arrangement::LargeDense, Arrangement::LooseRandom}) {
        for (const std::size_t count : {12u, 60u, 150u, 400u}) {
            for (const FallMode fall : {FallMode::Exact, FallMode::Step}) {
                for (const std::uint64_t seed : {1u, 2u, 3u, 4u}) {
                    PackRequest request;
                    request.count = count;
                    request.arrangement = a;
                    request.seed = seed;
                    request.protocol.fall = fall;
                    check_invariants(request, tally);
                }
            }
        }
    }
    BOOST_TEST(tally.packs == 128);
}

BOOST_AUTO_TEST_CASE(improved_protocol_options_keep_the_invariants) {
    Tally tally;
    const std::vector<std::function<void(ProtocolParams&)>> variants = {
        [](ProtocolParams& p) {
            p.sweep_stages = {8, 120, 720};
        },
        [](ProtocolParams& p) { p.gap = GapRule::Random; },
        [](ProtocolParams& p) { p.contact = ContactModel::Settle; },
        [](ProtocolParams& p) {
            p.contact = ContactModel::Settle;
            p.fall = FallMode::Step;
        },
        [](ProtocolParams& p) { p.contact = ContactModel::Roll; },
        [](ProtocolParams& p) {
            p.contact = ContactModel::Roll;
            p.fall = FallMode::Step;
        },
        [](ProtocolParams& p) {
            p.contact = ContactModel::Roll;
            p.walls = WallRule::Block;
        },
        [](ProtocolParams& p) { p.momentum = 0.5; },
        [](ProtocolParams& p) { p.walls = WallRule::Block; },
        [](ProtocolParams& p) {
            p.circle_factor = 10;
            p.sweep_stages = {3};
        },
    };
    for (const auto& change : variants) {
        for (const Arrangement a :
             {Arrangement::SingleColumn, Arrangement::LargeDense, Arrangement::LooseRandom}) {
            for (const std::uint64_t seed : {7u, 8u}) {
                PackRequest request;
                request.count = 300;
                request.arrangement = a;
                request.seed = seed;
                change(request.protocol);
                check_invariants(request, tally);
            }
        }
    }
    BOOST_TEST(tally.packs == 60);
}

BOOST_AUTO_TEST_CASE(multi_modal_packs_keep_the_invariants) {
    Tally tally;
    for (const Arrangement a : {Arrangement::SingleColumn, Arrangement::SmallDense,
                                Arrangement::LargeDense, Arrangement::LooseRandom}) {
        for (const FallMode fall : {FallMode::Exact, FallMode::Step}) {
            for (const std::uint64_t seed : {1u, 2u}) {
                PackRequest request;
                request.count = 300;
                request.arrangement = a;
                request.seed = seed;
                request.protocol.fall = fall;
                request.size_modes = {SizeMode{1.0, 0.5}, SizeMode{0.5, 0.3}, SizeMode{0.3, 0.2}};
                request.protocol.contact = seed == 2 ? ContactModel::Roll : ContactModel::None;
                check_invariants(request, tally);
            }
        }
    }
    BOOST_TEST(tally.packs == 16);
}

BOOST_AUTO_TEST_CASE(a_dense_target_still_gives_valid_packs) {
    Tally tally;
    for (const double phi : {0.3, kMaxPhiTarget}) {
        PackRequest request;
        request.count = 500;
        request.phi_target = phi;
        request.arrangement = Arrangement::SmallDense;
        check_invariants(request, tally);
    }
    BOOST_TEST(tally.packs == 2);
}

namespace {

/// The rolling contact model's promise (exact fall): every sphere on the floor, a wall, or
/// three earlier spheres that hold it in frictionless equilibrium (check_rolled_rest).
RestCheck rolled_rest(const PackRequest& request) {
    const Pack pack = make_pack(request);
    const double d = *pack.metadata.get_number("diameter");
    return check_rolled_rest(pack.particles, Container{}, 1e-9 * d, 1e-9);
}

PackRequest roll_request(std::size_t count, Arrangement arrangement, std::uint64_t seed) {
    PackRequest request;
    request.count = count;
    request.arrangement = arrangement;
    request.seed = seed;
    request.protocol.contact = ContactModel::Roll;
    return request;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_rolled_sphere_does_not_stay_on_top_of_one_or_two) {
    // Sphere 16 used to end on one earlier sphere, at the top of a two-sphere circle.
    PackRequest request = roll_request(29, Arrangement::SingleColumn, 385387);
    request.protocol.gap = GapRule::Largest;
    request.protocol.walls = WallRule::Block;
    const RestCheck check = rolled_rest(request);
    BOOST_TEST_INFO("first unrested index " << check.first);
    BOOST_TEST(check.unrested == 0u);
}

BOOST_AUTO_TEST_CASE(a_rolled_sphere_on_supports_is_in_frictionless_equilibrium) {
    // Sphere 393 used to end on two nearly level earlier spheres, pulled by neither.
    PackRequest request = roll_request(1948, Arrangement::SingleColumn, 282919);
    request.protocol.gap = GapRule::Random;
    const RestCheck check = rolled_rest(request);
    BOOST_TEST_INFO("first unrested index " << check.first);
    BOOST_TEST(check.unrested == 0u);
}

BOOST_AUTO_TEST_CASE(a_contact_made_at_the_overlap_tolerance_does_not_stop_the_roll) {
    // Sphere 4783 used to end on three spheres, one pulling: the contact made where a grazed
    // sphere's overlap reached the band's edge was met again at once on every later leg.
    PackRequest request = roll_request(4794, Arrangement::SingleColumn, 454711);
    request.protocol.fall = FallMode::Step;
    const RestCheck check = rolled_rest(request);
    BOOST_TEST_INFO("first unrested index " << check.first);
    BOOST_TEST(check.unrested == 0u);
}

BOOST_AUTO_TEST_CASE(every_rolled_sphere_rests_on_the_floor_a_wall_or_three_in_equilibrium) {
    // Seeds × arrangements × gap rule × wall rule × one and two size modes × both falls.
    int packs = 0;
    std::size_t unrested = 0;
    std::uint64_t seed = 100;
    for (const Arrangement a : {Arrangement::SingleColumn, Arrangement::SmallDense,
                                Arrangement::LargeDense, Arrangement::LooseRandom}) {
        for (const GapRule gap : {GapRule::Largest, GapRule::Random}) {
            for (const WallRule walls : {WallRule::Fix, WallRule::Block}) {
                for (const bool two_sizes : {false, true}) {
                    for (const std::size_t count : {40u, 200u, 350u, 600u}) {
                        PackRequest request = roll_request(count, a, ++seed);
                        request.protocol.gap = gap;
                        request.protocol.walls = walls;
                        // The step fall's last gap is closed by an exact fall before the roll.
                        request.protocol.fall = seed % 2 == 0 ? FallMode::Exact : FallMode::Step;
                        if (two_sizes)
                            request.size_modes = {SizeMode{1.0, 0.7}, SizeMode{0.5, 0.3}};
                        const RestCheck check = rolled_rest(request);
                        BOOST_TEST_INFO("count " << count << ", " << to_string(a) << ", seed "
                                                 << seed << ", gap " << to_string(gap)
                                                 << ", two sizes " << two_sizes << ", fall "
                                                 << to_string(request.protocol.fall));
                        BOOST_TEST(check.unrested == 0u);
                        unrested += check.unrested;
                        ++packs;
                    }
                }
            }
        }
    }
    BOOST_TEST(packs == 128);
    BOOST_TEST(unrested == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
