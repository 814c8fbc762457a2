#include <algorithm>
#include <array>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "brute_force.hpp"
#include "sgmp/engine/arrangement.hpp"

using namespace sgmp;
using namespace sgmp::engine;
namespace tt = boost::test_tools;

namespace {

constexpr std::array<Arrangement, 4> kAll = {Arrangement::SingleColumn, Arrangement::SmallDense,
                                             Arrangement::LargeDense, Arrangement::LooseRandom};
constexpr std::array<std::size_t, 8> kThesisCounts = {150, 300, 750, 1002, 2001, 3000, 6000, 9000};

}  // namespace

BOOST_AUTO_TEST_SUITE(arrangement)

BOOST_AUTO_TEST_CASE(names_round_trip_and_unknown_names_are_rejected) {
    for (const Arrangement a : kAll) {
        BOOST_TEST((parse_arrangement(to_string(a)) == a));
    }
    BOOST_TEST(to_string(Arrangement::LooseRandom) == "loose-random");
    BOOST_TEST(!parse_arrangement("loose_random").has_value());
    BOOST_TEST(!parse_arrangement("").has_value());
}

BOOST_AUTO_TEST_CASE(grid_columns_match_the_thesis_tables) {
    // Table 6.2 (small dense) and Table 7.2 (large dense). The thesis' 300-particle large
    // row reads 5x4; the rule floor(1.25/d) gives 5.
    const std::array<int, 8> small = {3, 4, 5, 6, 8, 9, 11, 13};
    const std::array<int, 8> large = {4, 5, 7, 8, 10, 11, 14, 16};
    for (std::size_t i = 0; i < kThesisCounts.size(); ++i) {
        const double d = diameter_for_count(kThesisCounts[i]);
        BOOST_TEST(grid_columns(Arrangement::SmallDense, d) == small[i]);
        BOOST_TEST(grid_columns(Arrangement::LargeDense, d) == large[i]);
    }
}

BOOST_AUTO_TEST_CASE(single_column_stands_on_the_floor_with_gaps_of_a_fifth_diameter) {
    const double d = diameter_for_count(300);
    Random rng(1);
    const auto ps = make_arrangement(Arrangement::SingleColumn, 300, d, rng);
    BOOST_TEST_REQUIRE(ps.size() == 300u);
    for (std::size_t i = 0; i < ps.size(); ++i) {
        BOOST_TEST(ps[i].id == static_cast<std::int64_t>(i + 1));
        BOOST_TEST(ps[i].center.x() == 0.0);
        BOOST_TEST(ps[i].center.z() == 0.0);
        BOOST_TEST(ps[i].radius == d / 2);
        BOOST_TEST(ps[i].center.y() == -0.625 + d / 2 + 1.2 * d * static_cast<double>(i),
                   tt::tolerance(1e-12));
    }
    // Height of the column: 299 gaps of 1.2 d plus one diameter.
    BOOST_TEST(starting_height(ps) == 299 * 1.2 * d + d, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(dense_layers_fill_their_square_and_stack_from_the_floor) {
    for (const std::size_t n : kThesisCounts) {
        const double d = diameter_for_count(n);
        for (const auto& [arrangement, half] :
             {std::pair{Arrangement::SmallDense, 0.5}, std::pair{Arrangement::LargeDense, 0.625}}) {
            Random rng(1);
            const auto ps = make_arrangement(arrangement, n, d, rng);
            const int columns = grid_columns(arrangement, d);
            const std::size_t per_layer = static_cast<std::size_t>(columns) * columns;
            const double spacing = 2 * half / columns;
            BOOST_TEST_REQUIRE(ps.size() == n);
            for (std::size_t i = 0; i < n; ++i) {
                const Vec3& c = ps[i].center;
                // Spheres lie within the square they span and on the layer grid.
                BOOST_TEST(std::abs(c.x()) + d / 2 <= half + 1e-12);
                BOOST_TEST(std::abs(c.z()) + d / 2 <= half + 1e-12);
                const double ix = (c.x() + half) / spacing - 0.5;
                BOOST_TEST(std::abs(ix - std::round(ix)) < 1e-9);
                const double layer = static_cast<double>(i / per_layer);
                BOOST_TEST(c.y() == -0.625 + d / 2 + d * layer, tt::tolerance(1e-12));
            }
            const double layers = std::ceil(static_cast<double>(n) / per_layer);
            BOOST_TEST(starting_height(ps) == layers * d, tt::tolerance(1e-12));
        }
    }
}

BOOST_AUTO_TEST_CASE(every_arrangement_is_inside_without_overlaps) {
    // Touching spheres (dense layers d apart) may show a rounding-level negative gap.
    for (const Arrangement a : kAll) {
        for (const std::size_t n : {2u, 37u, 150u, 1002u}) {
            const double d = diameter_for_count(n);
            Random rng(11);
            const auto ps = make_arrangement(a, n, d, rng);
            BOOST_TEST(testing::worst_pair_gap(ps) >= -1e-12 * d);
            BOOST_TEST(testing::worst_penetration(ps, Container{}) == 0.0);
        }
    }
}

BOOST_AUTO_TEST_CASE(loose_random_raises_its_level_only_on_collisions) {
    const std::size_t n = 1002;
    const double d = diameter_for_count(n);
    Random rng(5);
    const auto ps = make_arrangement(Arrangement::LooseRandom, n, d, rng);
    BOOST_TEST(ps.front().center.y() == -0.625 + d / 2);
    std::size_t raised = 0;
    for (std::size_t i = 1; i < n; ++i) {
        BOOST_TEST(ps[i].center.y() >= ps[i - 1].center.y());  // the level never drops
        if (ps[i].center.y() > ps[i - 1].center.y()) {
            ++raised;
            // A raised particle sits on (touches) one placed before it.
            const std::vector<Particle> before(ps.begin(), ps.begin() + static_cast<long>(i));
            double nearest = INFINITY;
            for (const Particle& p : before) {
                nearest = std::min(nearest, (p.center - ps[i].center).norm() - d);
            }
            BOOST_TEST(std::abs(nearest) < 1e-9 * d);
        }
    }
    BOOST_TEST(raised > 10u);
    // Different seeds give different clouds.
    Random other(6);
    BOOST_TEST(make_arrangement(Arrangement::LooseRandom, n, d, other)[3].center.x() !=
               ps[3].center.x());
}

BOOST_AUTO_TEST_SUITE_END()
