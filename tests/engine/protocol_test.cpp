#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "brute_force.hpp"
#include "refusal.hpp"
#include "sgmp/engine/protocol.hpp"
#include "sgmp/engine/sweep_table.hpp"

using namespace sgmp;
using namespace sgmp::engine;
namespace tt = boost::test_tools;

namespace {

constexpr double kR = 0.05;  // radius of the hand-made spheres
constexpr double kD = 2 * kR;
const Container kBox;

Particle sphere(double x, double y, double z, double r = kR) {
    return Particle{0, Vec3(x, y, z), r, 0};
}

double floor_y(double r = kR) {
    return kBox.floor + r;
}

/// The three spheres of a touching triangle on the floor around (cx, cz).
std::vector<Particle> triangle_bed(double cx, double cz) {
    std::vector<Particle> bed;
    const double circum = kD / std::sqrt(3.0);  // centroid-to-centre distance
    for (int k = 0; k < 3; ++k) {
        const double a = 2 * std::numbers::pi * k / 3;
        bed.push_back(sphere(cx + circum * std::cos(a), floor_y(), cz + circum * std::sin(a)));
    }
    return bed;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(protocol)

BOOST_AUTO_TEST_CASE(sweep_table_holds_samples_and_half_steps) {
    const SweepTable t(120);
    BOOST_TEST(t.positions() == 120);
    for (int h = 0; h < 240; h += 7) {
        const double theta = std::numbers::pi * h / 120;
        BOOST_TEST(t.x(h) == std::sin(theta));  // equation 4.1 (x = sin θ)
        BOOST_TEST(t.z(h) == std::cos(theta));  // equation 4.2 (z = cos θ)
    }
    BOOST_TEST(t.sample_x()[5] == t.x(10));
    BOOST_TEST(t.sample_z()[5] == t.z(10));
}

BOOST_AUTO_TEST_CASE(a_lone_sphere_falls_to_the_floor) {
    for (const FallMode mode : {FallMode::Exact, FallMode::Step}) {
        ProtocolParams params;
        params.fall = mode;
        const DropOutcome out = drop_onto({}, sphere(0.1, 3.0, -0.2), params);
        BOOST_TEST((out.reason == StopReason::Floor));
        BOOST_TEST(out.center.y() == floor_y());  // the floor is met exactly in both modes
        BOOST_TEST(out.center.x() == 0.1);
        BOOST_TEST(out.moves == 0);
    }
}

BOOST_AUTO_TEST_CASE(off_center_drop_slides_off_a_single_sphere_and_lands_lower) {
    const std::vector<Particle> bed = {sphere(0, floor_y(), 0)};
    const double offset = 0.3 * kR;
    const DropOutcome out = drop_onto(bed, sphere(offset, 1.0, 0), {});
    // First contact would be at y = y_bed + √(D² − offset²); it slides down to the floor.
    const double first_contact = floor_y() + std::sqrt(kD * kD - offset * offset);
    BOOST_TEST(out.center.y() < first_contact);
    BOOST_TEST((out.reason == StopReason::Floor));
    BOOST_TEST(out.center.y() == floor_y());
    BOOST_TEST(out.moves > 10);
    // It went away from the bed sphere along +x (the side it landed on) and clears it.
    BOOST_TEST(out.center.x() > offset);
    BOOST_TEST(std::abs(out.center.z()) < 1e-12);
    BOOST_TEST((out.center - bed[0].center).norm() >= kD * (1 - 1e-12));
}

BOOST_AUTO_TEST_CASE(step_fall_stops_less_than_one_step_above_the_contact) {
    const std::vector<Particle> bed = {sphere(0, floor_y(), 0)};
    ProtocolParams params;
    params.fall = FallMode::Step;
    params.fall_step = 0.001;
    params.max_moves = 1;  // stop after the first fall and sweep-move
    // Straight above the bed: the first fall ends on top, within one step.
    const DropOutcome out = drop_onto(bed, sphere(0, 0.4, 0), params);
    std::vector<Particle> all = bed;
    all.push_back(Particle{1, out.center, kR, 0});
    const double support = testing::support_distance(all, 1, kBox);
    BOOST_TEST(support >= 0.0);
    BOOST_TEST(support < 0.001);
    BOOST_TEST(testing::worst_pair_gap(all) >= 0.0);
}

BOOST_AUTO_TEST_CASE(drop_into_the_pocket_of_three_touching_spheres_rests_there) {
    const auto bed = triangle_bed(0.1, 0.2);
    // Analytic resting height: centroid distance d/√3, so the centre is d·√(2/3) above the
    // bed's centres.
    const double pocket_y = floor_y() + kD * std::sqrt(2.0 / 3.0);
    for (const FallMode mode : {FallMode::Exact, FallMode::Step}) {
        for (const double dx : {0.0, 0.01 * kD, 0.2 * kD}) {
            ProtocolParams params;
            params.fall = mode;
            const DropOutcome out = drop_onto(bed, sphere(0.1 + dx, 1.0, 0.2 - 0.5 * dx), params);
            BOOST_TEST_INFO("mode " << to_string(mode) << ", offset " << dx);
            // Exact: no free position left. Step: hovering within a step, it may instead stop
            // by the stall rule (moves without falling).
            BOOST_TEST((out.reason == StopReason::NoFreeArc ||
                        (mode == FallMode::Step && out.reason == StopReason::Stalled)));
            // It rests within a sweep radius (d/50) of the pocket, in height and across;
            // with the step fall also up to one step higher.
            const double slack = kD / 50 + (mode == FallMode::Step ? 0.001 : 0.0);
            BOOST_TEST(out.center.y() <= pocket_y + slack);
            BOOST_TEST(out.center.y() >= pocket_y - 1e-12);
            BOOST_TEST(std::hypot(out.center.x() - 0.1, out.center.z() - 0.2) <= kD / 50);
            std::vector<Particle> all = bed;
            all.push_back(Particle{4, out.center, kR, 0});
            BOOST_TEST(testing::worst_pair_gap(all) >= -1e-12 * kD);
        }
    }
}

BOOST_AUTO_TEST_CASE(exact_drop_into_the_pocket_ends_touching_and_settle_adds_a_contact) {
    const auto bed = triangle_bed(0.0, 0.0);
    const double pocket_y = floor_y() + kD * std::sqrt(2.0 / 3.0);
    ProtocolParams params;
    params.contact = ContactModel::Settle;
    const DropOutcome out = drop_onto(bed, sphere(0.15 * kD, 1.0, 0.05 * kD), params);
    int touching = 0;
    for (const Particle& p : bed) {
        const double gap = (p.center - out.center).norm() - kD;
        BOOST_TEST(gap >= -1e-12 * kD);
        touching += gap <= 1e-9 * kD ? 1 : 0;
    }
    BOOST_TEST(touching >= 2);  // rolled from its first contact onto a second
    BOOST_TEST(std::abs(out.center.y() - pocket_y) <= kD / 50);
}

BOOST_AUTO_TEST_CASE(the_rolling_contact_model_rests_in_the_pocket_on_all_three) {
    const auto bed = triangle_bed(0.0, 0.0);
    const double pocket_y = floor_y() + kD * std::sqrt(2.0 / 3.0);
    for (const FallMode mode : {FallMode::Exact, FallMode::Step}) {
        for (const double dx : {0.02 * kD, 0.15 * kD, 0.3 * kD}) {
            ProtocolParams params;
            params.contact = ContactModel::Roll;
            params.fall = mode;
            const DropOutcome out = drop_onto(bed, sphere(dx, 1.0, 0.4 * dx), params);
            BOOST_TEST_INFO("mode " << to_string(mode) << ", offset " << dx);
            // Stable on three touching supports: exactly the pocket (rounding only).
            BOOST_TEST(std::abs(out.center.y() - pocket_y) <= 1e-9 * kD);
            BOOST_TEST(std::hypot(out.center.x(), out.center.z()) <= 1e-9 * kD);
            for (const Particle& p : bed) {
                BOOST_TEST(std::abs((p.center - out.center).norm() - kD) <= 1e-9 * kD);
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(a_sphere_dropped_between_two_spheres_apart_ends_on_the_floor_beside_them) {
    // Centres 1.2·d apart: the falling sphere cannot pass between them, and the circle of
    // positions touching both dips below the floor, so it ends on the floor beside them.
    const std::vector<Particle> bed = {sphere(-0.6 * kD, floor_y(), 0),
                                       sphere(0.6 * kD, floor_y(), 0)};
    ProtocolParams params;
    params.contact = ContactModel::Roll;
    const DropOutcome out = drop_onto(bed, sphere(0.01 * kD, 1.0, 0.003), params);
    BOOST_TEST((out.reason == StopReason::Floor));
    BOOST_TEST(out.center.y() == floor_y());
    std::vector<Particle> all = bed;
    all.push_back(Particle{3, out.center, kR, 0});
    BOOST_TEST(testing::worst_pair_gap(all) >= -1e-10 * kD);
    BOOST_TEST(testing::support_distance(all, 2, kBox) <= 1e-9 * kD);
}

BOOST_AUTO_TEST_CASE(a_sphere_that_a_move_brings_to_a_wall_stops_there) {
    // Bed sphere near the +x wall; the falling one lands on its wall side and slides there.
    const double bed_x = kBox.x_max - 1.5 * kR;
    const std::vector<Particle> bed = {sphere(bed_x, floor_y(), 0)};
    const DropOutcome out = drop_onto(bed, sphere(bed_x + 0.3 * kR, 1.0, 0), {});
    BOOST_TEST((out.reason == StopReason::Wall));
    BOOST_TEST(out.center.x() + kR == kBox.x_max);  // touching the wall exactly
    BOOST_TEST(out.center.y() > floor_y() + kR);    // held up by the bed sphere and the wall
    BOOST_TEST((out.center - bed[0].center).norm() >= kD * (1 - 1e-12));
    // With blocking walls it slides down the wall side instead and reaches the floor... or
    // rests in the corner: either way it never crosses the wall.
    ProtocolParams block;
    block.walls = WallRule::Block;
    const DropOutcome blocked = drop_onto(bed, sphere(bed_x + 0.3 * kR, 1.0, 0), block);
    BOOST_TEST(blocked.center.x() + kR <= kBox.x_max);
    BOOST_TEST((blocked.reason != StopReason::Wall));
}

BOOST_AUTO_TEST_CASE(a_sphere_dropped_dead_center_on_another_leaves_in_a_random_direction) {
    const std::vector<Particle> bed = {sphere(0, floor_y(), 0)};
    const DropOutcome a = drop_onto(bed, sphere(0, 1.0, 0), {}, 1);
    const DropOutcome b = drop_onto(bed, sphere(0, 1.0, 0), {}, 2);
    BOOST_TEST((a.reason == StopReason::Floor));
    BOOST_TEST((b.reason == StopReason::Floor));
    BOOST_TEST((a.center - b.center).norm() > 1e-6);  // seeds pick different directions
    BOOST_TEST((a.center - drop_onto(bed, sphere(0, 1.0, 0), {}, 1).center).norm() == 0.0);
}

BOOST_AUTO_TEST_CASE(a_start_taken_by_a_settled_sphere_is_lifted_first) {
    // The settled sphere sits exactly where the falling one starts.
    const std::vector<Particle> bed = {sphere(0, floor_y(), 0)};
    const DropOutcome out = drop_onto(bed, sphere(0.2 * kR, floor_y() + 0.1 * kR, 0), {});
    std::vector<Particle> all = bed;
    all.push_back(Particle{1, out.center, kR, 0});
    BOOST_TEST(testing::worst_pair_gap(all) >= -1e-12 * kD);
}

BOOST_AUTO_TEST_CASE(multi_stage_sweep_tries_finer_stages_only_when_needed) {
    const auto bed = triangle_bed(0.0, 0.0);
    ProtocolParams coarse;
    coarse.sweep_stages = {4};
    ProtocolParams staged;
    staged.sweep_stages = {4, 120, 720};
    const Particle start = sphere(0.02 * kD, 1.0, -0.01 * kD);
    const DropOutcome a = drop_onto(bed, start, coarse);
    const DropOutcome b = drop_onto(bed, start, staged);
    const double pocket_y = floor_y() + kD * std::sqrt(2.0 / 3.0);
    // The finer stages, tried when four positions 90° apart are all blocked, never leave
    // it higher.
    BOOST_TEST(a.center.y() >= pocket_y - 1e-12);
    BOOST_TEST(b.center.y() >= pocket_y - 1e-12);
    BOOST_TEST(b.center.y() <= a.center.y());
    BOOST_TEST(b.center.y() - pocket_y < kD / 50);
}

BOOST_AUTO_TEST_CASE(parameters_are_validated_with_the_option_named) {
    const auto error_for = [](auto change) {
        ProtocolParams p;
        change(p);
        return refusal([&] { validate(p, 0.1); });
    };
    BOOST_TEST(refusal([&] { validate(ProtocolParams{}, 0.1); }).empty());
    BOOST_TEST(error_for([](auto& p) { p.circle_factor = 1; }).find("--circle-factor 1") == 0u);
    BOOST_TEST(error_for([](auto& p) { p.sweep_stages = {2}; }).find("--sweep-positions 2") == 0u);
    BOOST_TEST(error_for([](auto& p) { p.sweep_stages = {8, 8}; }).find("--sweep-stages") == 0u);
    BOOST_TEST(error_for([](auto& p) { p.fall_step = 0; }).find("--fall-step 0") == 0u);
    // A step at least the (smallest) diameter is refused for the step fall only: the exact
    // fall never uses it (a blend with fines below the default step must pack).
    BOOST_TEST(error_for([](auto& p) {
                   p.fall = FallMode::Step;
                   p.fall_step = 0.1;
               }).find("--fall-step 0.1") == 0u);
    BOOST_TEST(error_for([](auto& p) { p.fall_step = 0.1; }).empty());
    BOOST_TEST(error_for([](auto& p) { p.fall_step = INFINITY; }).find("--fall-step") == 0u);
    BOOST_TEST(error_for([](auto& p) { p.fall_step = NAN; }).find("--fall-step") == 0u);
    BOOST_TEST(error_for([](auto& p) { p.lower_neighbours = 0; }).find("--lower-neighbours") == 0u);
    BOOST_TEST(error_for([](auto& p) { p.momentum = 1; }).find("--momentum 1") == 0u);
    BOOST_TEST((parse_stages("8,120,720") == std::vector<int>({8, 120, 720})));
    BOOST_TEST(!parse_stages("8,,720").has_value());
    BOOST_TEST(!parse_stages("8x").has_value());
}

BOOST_AUTO_TEST_SUITE_END()
