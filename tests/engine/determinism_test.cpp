#include <boost/test/unit_test.hpp>

#include "refusal.hpp"
#include "sgmp/engine/make_pack.hpp"

using namespace sgmp;
using namespace sgmp::engine;

BOOST_AUTO_TEST_SUITE(determinism)

BOOST_AUTO_TEST_CASE(same_request_gives_the_same_pack_bit_for_bit) {
    for (const Arrangement a : {Arrangement::SingleColumn, Arrangement::LooseRandom}) {
        PackRequest request;
        request.count = 500;
        request.arrangement = a;
        request.seed = 42;
        request.protocol.gap = GapRule::Random;
        const Pack first = make_pack(request);
        const Pack second = make_pack(request);
        BOOST_TEST_REQUIRE(first.particles.size() == second.particles.size());
        for (std::size_t i = 0; i < first.particles.size(); ++i) {
            BOOST_TEST((first.particles[i].center == second.particles[i].center));
            BOOST_TEST(first.particles[i].color == second.particles[i].color);
        }
        BOOST_TEST((first.metadata.entries() == second.metadata.entries()));
        request.seed = 43;
        BOOST_TEST((make_pack(request).particles[100].center != first.particles[100].center));
    }
}

BOOST_AUTO_TEST_CASE(a_pack_starts_from_make_arrangement_with_the_same_seed) {
    // What a reference pour started from the same state relies on.
    for (const Arrangement a : {Arrangement::LooseRandom, Arrangement::SmallDense}) {
        PackRequest request;
        request.count = 700;
        request.arrangement = a;
        request.seed = 12;
        Random rng(12);
        const auto expected = make_arrangement(a, 700, diameter_for_count(700), rng);
        const Pack start = make_start_pack(request);
        BOOST_TEST_REQUIRE(start.particles.size() == expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i) {
            BOOST_TEST((start.particles[i].center == expected[i].center));
            BOOST_TEST(start.particles[i].color == expected[i].color);
            BOOST_TEST(start.particles[i].id == expected[i].id);
        }
        // And the pack keeps ids and colours of its start.
        const Pack pack = make_pack(request);
        BOOST_TEST(pack.particles[500].id == expected[500].id);
        BOOST_TEST(pack.particles[500].color == expected[500].color);
    }
}

BOOST_AUTO_TEST_CASE(metadata_records_tool_parameters_and_seed) {
    PackRequest request;
    request.count = 150;
    request.arrangement = Arrangement::SmallDense;
    request.seed = 9;
    request.protocol.sweep_stages = {8, 120, 720};
    request.protocol.fall = FallMode::Step;
    PackStats stats;
    const Pack pack = make_pack(request, {}, &stats);
    const Metadata& m = pack.metadata;
    BOOST_TEST(m.get("generator").value_or("") == "sgmp");
    BOOST_TEST(m.contains("version"));
    BOOST_TEST(m.get("count").value_or("") == "150");
    BOOST_TEST(*m.get_number("diameter") == diameter_for_count(150));
    BOOST_TEST(m.get("phi_target").value_or("") == "0.63");
    BOOST_TEST(m.get("arrangement").value_or("") == "small-dense");
    BOOST_TEST(m.get("seed").value_or("") == "9");
    BOOST_TEST(m.get("circle_factor").value_or("") == "50");
    BOOST_TEST(m.get("sweep_stages").value_or("") == "8,120,720");
    BOOST_TEST(m.get("lower_neighbours").value_or("") == "10");
    BOOST_TEST(m.get("gap").value_or("") == "largest");
    BOOST_TEST(m.get("fall").value_or("") == "step");
    BOOST_TEST(m.get("fall_step").value_or("") == "0.001");
    BOOST_TEST(m.get("contact").value_or("") == "none");
    BOOST_TEST(m.get("momentum").value_or("") == "0");
    BOOST_TEST(m.get("walls").value_or("") == "fix");
    BOOST_TEST(m.contains("stall_moves"));
    BOOST_TEST(m.contains("max_moves"));
    BOOST_TEST(m.get("container").value_or("") == "-0.625 0.625 -0.625 0.625 -0.625");
    BOOST_TEST(*m.get_number("start_height") == stats.start_height);
    // Every particle stopped for one of the counted reasons.
    BOOST_TEST(stats.on_floor + stats.at_wall + stats.resting + stats.stalled + stats.move_limit ==
               150u);
}

BOOST_AUTO_TEST_CASE(progress_is_reported_up_to_the_total) {
    PackRequest request;
    request.count = 2500;
    request.arrangement = Arrangement::LargeDense;
    std::vector<std::size_t> seen;
    make_pack(request, [&](std::size_t done, std::size_t total) {
        BOOST_TEST(total == 2500u);
        seen.push_back(done);
    });
    BOOST_TEST(seen == std::vector<std::size_t>({1000, 2000, 2500}));
}

BOOST_AUTO_TEST_CASE(bad_requests_are_refused_with_the_option_named) {
    PackRequest request;
    request.count = 0;
    BOOST_TEST(refusal([&] { validate(request); }).find("--count 0") == 0u);
    request.count = kMaxCount + 1;
    BOOST_TEST(refusal([&] { validate(request); }).find("--count") == 0u);
    request.count = 100;
    request.phi_target = 0.0;
    BOOST_TEST(refusal([&] { validate(request); }).find("--phi-target 0") == 0u);
    request.phi_target = 0.74049;
    BOOST_TEST(refusal([&] { validate(request); }).find("--phi-target 0.74049") == 0u);
    request.phi_target = kMaxPhiTarget;
    BOOST_TEST(refusal([&] { validate(request); }).empty());
    PackRequest empty;
    empty.count = 0;
    BOOST_CHECK_THROW(make_pack(empty), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
