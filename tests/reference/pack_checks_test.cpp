// Checks of settled packs: overlaps, walls, packing fraction, colour labels.
#include <array>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "sgmp/pack/sphere_box_volume.hpp"
#include "sgmp/reference/colours.hpp"
#include "sgmp/reference/pack_checks.hpp"

using namespace sgmp;
using namespace sgmp::reference;

namespace {

Particle sphere(std::int64_t id, double x, double y, double z, double r) {
    return Particle{id, Vec3(x, y, z), r, 0};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pack_checks)

BOOST_AUTO_TEST_CASE(the_largest_pair_overlap_is_found) {
    Pack pack;
    pack.particles = {sphere(1, 0.0, 0.0, 0.0, 0.1), sphere(2, 0.199, 0.0, 0.0, 0.1),
                      sphere(3, 0.4, 0.0, 0.0, 0.1), sphere(4, 0.4, 0.197, 0.0, 0.1),
                      sphere(5, -0.3, 0.0, 0.0, 0.1)};
    const OverlapSummary s = pair_overlaps(pack);
    BOOST_TEST(s.overlapping_pairs == 2u);  // 1-2 (0.001) and 3-4 (0.003); 2-3 are 0.001 apart
    BOOST_TEST(s.max_overlap == 0.003, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(overlaps_across_cell_boundaries_are_found) {
    Pack pack;  // centres on both sides of the cell boundary at 0 (cells of side 0.2)
    pack.particles = {sphere(1, -0.0995, -0.001, 0.0, 0.1), sphere(2, 0.0995, 0.001, 0.0, 0.1)};
    BOOST_TEST(pair_overlaps(pack).max_overlap == 0.2 - std::hypot(0.199, 0.002),
               boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(wall_and_floor_penetration) {
    Pack pack;
    pack.particles = {sphere(1, 0.0, -0.62, 0.0, 0.01), sphere(2, 0.6, 0.0, 0.0, 0.03)};
    BOOST_TEST(max_wall_penetration(pack, Container{}) == 0.005,
               boost::test_tools::tolerance(1e-12));
    pack.particles = {sphere(1, 0.0, -0.6, 0.0, 0.025)};
    BOOST_TEST(max_wall_penetration(pack, Container{}) == 0.0);
}

BOOST_AUTO_TEST_CASE(packing_fraction_counts_only_the_part_inside) {
    Pack pack;
    pack.particles = {sphere(1, 0.0, 0.0, 0.0, 0.2), sphere(2, 0.5, 0.0, 0.0, 0.2),
                      sphere(3, 2.0, 0.0, 0.0, 0.2)};
    const double v = 4.0 / 3.0 * std::numbers::pi * 0.008;
    BOOST_TEST(packing_fraction(pack, control_volume()) == 1.5 * v,
               boost::test_tools::tolerance(1e-10));
}

BOOST_AUTO_TEST_CASE(colour_bins_are_emptied_evenly) {
    std::vector<Particle> particles(1002);
    Random random(3);
    assign_colours(particles, random);
    std::array<int, kColourBins> counts{};
    for (const auto& p : particles) {
        BOOST_TEST_REQUIRE((p.color >= 0 && p.color < kColourBins));
        ++counts[static_cast<std::size_t>(p.color)];
    }
    for (int b = 0; b < kColourBins; ++b) {
        BOOST_TEST(counts[static_cast<std::size_t>(b)] == (b < 2 ? 101 : 100));
    }
    std::vector<Particle> again(1002);
    Random same(3);
    assign_colours(again, same);
    BOOST_TEST(again[500].color == particles[500].color);
}

BOOST_AUTO_TEST_SUITE_END()
