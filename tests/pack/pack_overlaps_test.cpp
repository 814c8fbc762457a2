// The pack library's neighbour kernel (CellGrid), overlap search, colour bins and the
// packing fraction of a region, on hand-made cases with known answers and against brute
// force.
#include <array>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include "sgmp/pack/cell_grid.hpp"
#include "sgmp/pack/color_bins.hpp"
#include "sgmp/pack/pack_overlaps.hpp"
#include "sgmp/pack/random.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"
#include "test_support.hpp"

using namespace sgmp;

namespace {

using sgmp::testing::sphere;

std::vector<Particle> random_spheres(std::size_t n, double spread, std::uint64_t seed) {
    Random random(seed);
    std::vector<Particle> ps;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 c(random.uniform(-spread, spread), random.uniform(-spread, spread),
                     random.uniform(-spread, spread));
        ps.push_back(sphere(static_cast<std::int64_t>(i + 1), c.x(), c.y(), c.z(),
                            random.uniform(0.01, 0.03)));
    }
    return ps;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pack_overlaps)

BOOST_AUTO_TEST_CASE(the_largest_pair_overlap_is_found) {
    const std::vector<Particle> ps = {
        sphere(1, 0.0, 0.0, 0.0, 0.1), sphere(2, 0.199, 0.0, 0.0, 0.1),
        sphere(3, 0.4, 0.0, 0.0, 0.1), sphere(4, 0.4, 0.197, 0.0, 0.1),
        sphere(5, -0.3, 0.0, 0.0, 0.1)};
    const OverlapCount c = count_overlaps(ps, Container{}, 0.0);
    BOOST_TEST(c.pairs == 2u);  // 1-2 (0.001) and 3-4 (0.003); 2-3 are 0.001 apart
    BOOST_TEST(c.max_pair == 0.003, boost::test_tools::tolerance(1e-12));
    // A tolerance of 0.002 keeps only the deeper one; the deepest depth is still reported.
    const OverlapCount deep = count_overlaps(ps, Container{}, 0.002);
    BOOST_TEST(deep.pairs == 1u);
    BOOST_TEST(deep.max_pair == 0.003, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(overlaps_across_cell_boundaries_are_found) {
    const std::vector<Particle> ps = {sphere(1, -0.0995, -0.001, 0.0, 0.1),
                                      sphere(2, 0.0995, 0.001, 0.0, 0.1)};
    BOOST_TEST(count_overlaps(ps, Container{}, 0.0).max_pair == 0.2 - std::hypot(0.199, 0.002),
               boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(wall_and_floor_penetration) {
    std::vector<Particle> ps = {sphere(1, 0.0, -0.62, 0.0, 0.01), sphere(2, 0.6, 0.0, 0.0, 0.03)};
    const OverlapCount c = count_overlaps(ps, Container{}, 0.0);
    BOOST_TEST(c.max_wall == 0.005, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(c.walls == 2u);
    ps = {sphere(1, 0.0, -0.6, 0.0, 0.025)};  // exactly touching the floor
    BOOST_TEST(count_overlaps(ps, Container{}, 0.0).max_wall == 0.0);
}

BOOST_AUTO_TEST_CASE(pairs_match_brute_force_over_seeds_and_spreads) {
    // Dense (cells of side 2·r_max) and very spread out (the grid widens its cells to keep
    // at most 2N + 64 of them): the same pair set as the O(N²) loop, exactly.
    for (const double spread : {0.2, 0.6, 1e6}) {
        for (std::uint64_t seed = 1; seed <= 8; ++seed) {
            std::vector<Particle> ps = random_spheres(400, spread, seed);
            if (spread > 1.0) {  // a few close pairs among far-flung spheres
                ps[1].center = ps[0].center + Vec3(0.02, 0.0, 0.0);
                ps[3].center = ps[2].center + Vec3(0.0, 0.01, 0.01);
            }
            std::set<std::pair<std::size_t, std::size_t>> fast;
            for_each_overlap(
                ps, Container{},
                [&](std::size_t i, std::size_t j, double) {
                    fast.insert({i, j});
                },
                [](std::size_t, double) {});
            std::set<std::pair<std::size_t, std::size_t>> brute;
            for (std::size_t i = 0; i < ps.size(); ++i) {
                for (std::size_t j = i + 1; j < ps.size(); ++j) {
                    if (ps[i].radius + ps[j].radius - (ps[i].center - ps[j].center).norm() > 0.0) {
                        brute.insert({i, j});
                    }
                }
            }
            BOOST_TEST_REQUIRE(fast == brute);
            BOOST_TEST((spread > 0.3 || !brute.empty()));  // the dense case has overlaps
        }
    }
}

BOOST_AUTO_TEST_CASE(a_wide_blend_finds_every_pair_once_in_order) {
    // Radii 0.01–0.03 and a few of 0.2–0.3 (r_max > 2 r_min: cells for the small spheres,
    // the large ones searched beyond them): the pair list of the O(N²) loop, each pair
    // once with i < j, and every work item [first, last) giving its own pairs in order.
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        std::vector<Particle> ps = random_spheres(600, 0.4, seed);
        Random random(seed + 100);
        for (std::size_t i = 0; i < ps.size(); i += 37) {
            ps[i].radius = random.uniform(0.2, 0.3);
        }
        std::vector<std::pair<std::size_t, std::size_t>> fast;
        const OverlapSearch search(ps);
        for (std::size_t first = 0; first < ps.size(); first += 97) {
            std::vector<std::pair<std::size_t, std::size_t>> item;
            search.pairs_from(first, std::min(ps.size(), first + 97),
                              [&](std::size_t i, std::size_t j, double depth) {
                                  BOOST_TEST(i < j);
                                  BOOST_TEST(i >= first);
                                  BOOST_TEST(depth > 0.0);
                                  item.emplace_back(i, j);
                              });
            fast.insert(fast.end(), item.begin(), item.end());
        }
        std::set<std::pair<std::size_t, std::size_t>> unique(fast.begin(), fast.end());
        BOOST_TEST(unique.size() == fast.size());  // none twice
        std::set<std::pair<std::size_t, std::size_t>> brute;
        for (std::size_t i = 0; i < ps.size(); ++i) {
            for (std::size_t j = i + 1; j < ps.size(); ++j) {
                if (ps[i].radius + ps[j].radius - (ps[i].center - ps[j].center).norm() > 0.0) {
                    brute.insert({i, j});
                }
            }
        }
        BOOST_TEST_REQUIRE(unique == brute);
        BOOST_TEST(brute.size() > 100u);
    }
}

BOOST_AUTO_TEST_CASE(near_queries_of_any_radius_match_brute_force) {
    const std::vector<Particle> ps = random_spheres(300, 0.5, 11);
    const CellGrid grid(centers_of(ps), 0.05);
    for (const double radius : {0.0, 0.03, 0.05, 0.31, double(INFINITY)}) {
        const Vec3 p(0.1, -0.2, 0.05);
        std::set<std::size_t> fast;
        grid.for_each_near(p, radius, [&](std::size_t j, double) { fast.insert(j); });
        std::set<std::size_t> brute;
        for (std::size_t j = 0; j < ps.size(); ++j) {
            if ((ps[j].center - p).norm() <= radius) {
                brute.insert(j);
            }
        }
        BOOST_TEST(fast == brute);
    }
}

BOOST_AUTO_TEST_CASE(centres_spread_beyond_any_integer_grid_still_give_a_grid) {
    // 10²⁰ over a reach of 0.2 is 5·10²⁰ cells per axis, beyond int64: the grid widens its
    // cells instead (it once cast the count and threw std::length_error). Near ±10³⁰⁸ the
    // span itself is infinite: one cell.
    for (const double far : {1e20, 1e300, 1.7e308}) {
        BOOST_TEST_INFO("far " << far);
        const std::vector<Vec3> centers{Vec3(-far, 0, 0), Vec3(0, 0, 0), Vec3(0.1, 0, 0),
                                        Vec3(far, 0, 0)};
        const CellGrid grid(centers, 0.2);
        std::size_t pairs = 0;
        grid.for_each_pair([&](std::size_t i, std::size_t j, double) {
            BOOST_TEST((i == 1 && j == 2));
            ++pairs;
        });
        BOOST_TEST(pairs == 1u);
    }
}

BOOST_AUTO_TEST_CASE(a_center_that_is_not_finite_is_refused) {
    std::vector<Vec3> centers = {Vec3(0, 0, 0), Vec3(NAN, 0, 0)};
    BOOST_CHECK_THROW(CellGrid(centers, 0.1), std::invalid_argument);
    BOOST_CHECK_THROW(CellGrid({Vec3(0, 0, 0)}, 0.0), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(packing_fraction_counts_only_the_part_inside) {
    Pack pack;
    pack.particles = {sphere(1, 0.0, 0.0, 0.0, 0.2), sphere(2, 0.5, 0.0, 0.0, 0.2),
                      sphere(3, 2.0, 0.0, 0.0, 0.2)};
    const double v = 4.0 / 3.0 * std::numbers::pi * 0.008;
    BOOST_TEST(packing_fraction(pack, control_volume()) == 1.5 * v,
               boost::test_tools::tolerance(1e-10));
}

BOOST_AUTO_TEST_CASE(color_bins_share_the_particles_evenly) {
    for (const std::size_t n : {1u, 9u, 10u, 1002u}) {
        Random rng(3);
        const std::vector<int> colors = draw_colors(n, rng);
        BOOST_TEST(colors.size() == n);
        std::array<std::size_t, kColorBins> count{};
        for (const int c : colors) {
            BOOST_TEST_REQUIRE((c >= 0 && c < kColorBins));
            ++count[static_cast<std::size_t>(c)];
        }
        for (int k = 0; k < kColorBins; ++k) {
            BOOST_TEST(count[static_cast<std::size_t>(k)] ==
                       n / 10 + (static_cast<std::size_t>(k) < n % 10 ? 1u : 0u));
        }
    }
    // The order is random and reproducible: two seeds differ, the same seed repeats.
    Random a(1);
    Random b(2);
    BOOST_TEST(draw_colors(100, a) != draw_colors(100, b));
    Random c(5);
    Random c_again(5);
    BOOST_TEST(draw_colors(1002, c) == draw_colors(1002, c_again));
}

BOOST_AUTO_TEST_SUITE_END()
