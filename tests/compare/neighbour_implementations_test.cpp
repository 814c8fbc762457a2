// One test body run over every neighbour search of the testbed — the pack library's
// CellGrid, the engine's SettledGrid and compare's CGAL kd-tree — plus a cross-check that
// demands identical pair sets from all of them and from brute force.
#include <boost/mpl/list.hpp>
#include <boost/test/unit_test.hpp>
#include <set>
#include <utility>
#include <vector>

#include "sgmp/engine/settled_grid.hpp"
#include "sgmp/metrics/neighbour_index.hpp"
#include "sgmp/pack/cell_grid.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;

namespace {

using PairSet = std::set<std::pair<std::size_t, std::size_t>>;

/// Pairs i < j with |p_i − p_j| ≤ cutoff, by brute force.
PairSet brute_pairs(const std::vector<Vec3>& points, double cutoff) {
    PairSet pairs;
    for (std::size_t i = 0; i < points.size(); ++i) {
        for (std::size_t j = i + 1; j < points.size(); ++j) {
            if ((points[i] - points[j]).squaredNorm() <= cutoff * cutoff) {
                pairs.insert({i, j});
            }
        }
    }
    return pairs;
}

struct CellGridSearch {
    static PairSet pairs(const std::vector<Vec3>& points, double cutoff) {
        const CellGrid grid(points, cutoff);
        PairSet pairs;
        for (std::size_t i = 0; i < points.size(); ++i) {
            grid.for_each_near(points[i], cutoff, [&](std::size_t j, double) {
                if (j > i) {
                    pairs.insert({i, j});
                }
            });
        }
        return pairs;
    }
};

struct SettledGridSearch {
    static PairSet pairs(const std::vector<Vec3>& points, double cutoff) {
        engine::SettledGrid grid(Container{}, cutoff);
        for (const Vec3& p : points) {
            grid.insert(engine::Sphere{p.x(), p.y(), p.z(), 0.0});
        }
        // The grid stores coordinates only; find each stored sphere's index by its centre
        // (the generated points are distinct).
        PairSet pairs;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const Vec3 span = Vec3::Constant(cutoff);
            grid.for_each_in_box(points[i] - span, points[i] + span, [&](const engine::Sphere& s) {
                const Vec3 q(s.x, s.y, s.z);
                if ((q - points[i]).squaredNorm() > cutoff * cutoff) {
                    return;
                }
                for (std::size_t j = i + 1; j < points.size(); ++j) {
                    if (points[j] == q) {
                        pairs.insert({i, j});
                    }
                }
            });
        }
        return pairs;
    }
};

struct KdTreeSearch {
    static PairSet pairs(const std::vector<Vec3>& points, double cutoff) {
        const metrics::NeighbourIndex index(points);
        PairSet pairs;
        std::vector<metrics::Index> found;
        for (std::size_t i = 0; i < points.size(); ++i) {
            index.within(points[i], cutoff, found);
            for (const metrics::Index j : found) {
                if (j > i) {
                    pairs.insert({i, j});
                }
            }
        }
        return pairs;
    }
};

using Searches = boost::mpl::list<CellGridSearch, SettledGridSearch, KdTreeSearch>;

/// Random points inside the container, plus a cubic lattice of spacing exactly `cutoff`
/// (binary fractions, so lattice neighbours sit exactly on the cutoff sphere).
std::vector<Vec3> test_points(std::uint64_t seed, std::size_t count, double cutoff) {
    Random random(seed);
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < count; ++i) {
        points.emplace_back(random.uniform(-0.6, 0.6), random.uniform(-0.6, 0.6),
                            random.uniform(-0.6, 0.6));
    }
    for (int x = 0; x < 4; ++x) {
        for (int y = 0; y < 4; ++y) {
            for (int z = 0; z < 4; ++z) {
                points.emplace_back(-0.5 + x * cutoff, -0.5 + y * cutoff, -0.5 + z * cutoff);
            }
        }
    }
    return points;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(neighbour_implementations)

BOOST_AUTO_TEST_CASE_TEMPLATE(every_search_finds_exactly_the_brute_force_pairs, Search, Searches) {
    for (const double cutoff : {0.0625, 0.125, 0.25}) {
        for (std::uint64_t seed = 1; seed <= 5; ++seed) {
            const std::vector<Vec3> points = test_points(seed, 500, cutoff);
            const PairSet expected = brute_pairs(points, cutoff);
            BOOST_TEST_REQUIRE(Search::pairs(points, cutoff) == expected);
            // The lattice alone contributes 3·4·4·3 = 144 pairs exactly at the cutoff.
            BOOST_TEST_REQUIRE(expected.size() >= 144u);
        }
    }
}

BOOST_AUTO_TEST_CASE(all_searches_agree_with_each_other) {
    const std::vector<Vec3> points = test_points(42, 2000, 0.125);
    const PairSet cells = CellGridSearch::pairs(points, 0.125);
    BOOST_TEST(cells == SettledGridSearch::pairs(points, 0.125));
    BOOST_TEST(cells == KdTreeSearch::pairs(points, 0.125));
    BOOST_TEST(cells.size() > 2000u);
}

BOOST_AUTO_TEST_SUITE_END()
