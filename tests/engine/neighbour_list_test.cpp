// NeighbourList (the relaxation's Verlet list) against brute force: every pair i < j whose
// centres are closer than rᵢ + rⱼ + skin, minimum image in x and z when periodic, is listed
// under i, and no other. The criterion is the same arithmetic in both (squared distance
// against squared reach), so the sets must be equal, not close.
#include "sgmp/engine/neighbour_list.hpp"

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <set>
#include <utility>
#include <vector>

#include "sgmp/pack/random.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

using Pairs = std::set<std::pair<std::uint32_t, std::uint32_t>>;

std::vector<Ball> random_balls(std::size_t count, const Container& c, std::uint64_t seed) {
    Random random(seed);
    std::vector<Ball> balls(count);
    for (Ball& b : balls) {
        b.r = random.uniform(0.01, 0.05);  // a 5 : 1 blend
        b.x = random.uniform(c.x_min, c.x_max);
        b.y = random.uniform(c.floor, c.floor + 1.0);
        b.z = random.uniform(c.z_min, c.z_max);
    }
    return balls;
}

Pairs brute_force(const std::vector<Ball>& s, double skin, const Container& sides) {
    Pairs pairs;
    for (std::uint32_t i = 0; i < s.size(); ++i) {
        for (std::uint32_t j = i + 1; j < s.size(); ++j) {
            double dx = s[j].x - s[i].x;
            const double dy = s[j].y - s[i].y;
            double dz = s[j].z - s[i].z;
            sides.to_nearest_image(dx, dz);
            const double reach = s[i].r + s[j].r + skin;
            if (dx * dx + dy * dy + dz * dz < reach * reach) {
                pairs.emplace(i, j);
            }
        }
    }
    return pairs;
}

Pairs listed(const NeighbourList& list, std::size_t count) {
    Pairs pairs;
    for (std::uint32_t i = 0; i < count; ++i) {
        BOOST_TEST(list.first_slot(i) <= list.pairs());
        for (const std::uint32_t j : list.of(i)) {
            BOOST_TEST(j > i);
            BOOST_TEST(pairs.emplace(i, j).second, "pair listed twice");
        }
    }
    return pairs;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(neighbour_list)

BOOST_AUTO_TEST_CASE(walls_and_periodic_cells_list_exactly_the_brute_force_pairs) {
    Container walls;  // the testbed's container, 1.25 wide
    Container periodic = walls;
    periodic.periodic = true;
    NeighbourList list;  // reused across builds, as the relaxation does
    std::size_t total = 0;
    for (const Container& sides : {walls, periodic}) {
        for (const std::uint64_t seed : {1u, 2u, 3u, 4u}) {
            for (const double skin : {0.0, 0.004, 0.03}) {
                const auto balls = random_balls(1500, sides, seed);
                list.build(balls, skin, sides);
                const Pairs expected = brute_force(balls, skin, sides);
                BOOST_TEST((listed(list, balls.size()) == expected),
                           "seed " << seed << " skin " << skin << " periodic " << sides.periodic);
                BOOST_TEST(list.pairs() == expected.size());
                total += expected.size();
            }
        }
    }
    BOOST_TEST(total > 10000u);  // the cases hold many pairs, across cell and period edges
}

BOOST_AUTO_TEST_CASE(periodic_pairs_across_the_cell_edge_are_found) {
    // Two spheres 0.02 apart through the x period (x = ±0.615), and their z twins.
    Container sides;
    sides.periodic = true;
    const std::vector<Ball> balls{{-0.615, 0.0, 0.0, 0.01},
                                  {0.615, 0.0, 0.0, 0.01},
                                  {0.0, 0.0, -0.615, 0.01},
                                  {0.0, 0.0, 0.615, 0.01}};
    NeighbourList list;
    list.build(balls, 0.001, sides);
    BOOST_TEST((listed(list, balls.size()) == Pairs{{0, 1}, {2, 3}}));
    list.build(balls, 0.001, Container{});  // walls: nothing touches
    BOOST_TEST(list.pairs() == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
