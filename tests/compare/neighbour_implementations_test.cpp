// Every neighbour search of the testbed against brute force. The two implementations of
// the neighbour-query vocabulary (sgmp/pack/neighbour_query.hpp) — the pack library's
// CellGrid and compare's CGAL kd-tree NeighbourIndex — run one test body, in an open and
// in a periodic box: radius queries, pairs and k nearest must equal brute force over the
// box's own distance exactly (lattice points sit exactly on the radius, also across the
// periodic faces). The engine's incremental SettledGrid, the relaxation's Verlet list
// (NeighbourList) and the metrics' pair columns (PairColumns) must give the brute-force
// pair sets too, open and periodic (the grid and the columns through the images their
// users add).
#include <algorithm>
#include <boost/mpl/list.hpp>
#include <boost/test/unit_test.hpp>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "sgmp/engine/neighbour_list.hpp"
#include "sgmp/engine/settled_grid.hpp"
#include "sgmp/metrics/neighbour_index.hpp"
#include "sgmp/metrics/pair_columns.hpp"
#include "sgmp/pack/cell_grid.hpp"
#include "sgmp/pack/neighbour_query.hpp"
#include "sgmp/pack/periodic_images.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;

namespace {

using PairSet = std::set<std::pair<std::size_t, std::size_t>>;

static_assert(NeighbourQuery<CellGrid>);
static_assert(NeighbourQuery<metrics::NeighbourIndex>);

/// The testbed's 1.25-wide cell, periodic in x and z.
Container periodic_sides() {
    Container sides;
    sides.periodic = true;
    return sides;
}

NeighbourBox periodic_box() {
    return NeighbourBox::of(periodic_sides());
}

/// Random points in the cell (y over [-0.6, 0.6]), plus lattices of spacing exactly
/// `cutoff` (binary fractions): one inside, and one whose rows straddle the x and z faces,
/// so that neighbours sit exactly at the cutoff, directly or through a period.
std::vector<Vec3> test_points(std::uint64_t seed, std::size_t count, double cutoff) {
    Random random(seed);
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < count; ++i) {
        points.emplace_back(random.uniform(-0.625, 0.625), random.uniform(-0.6, 0.6),
                            random.uniform(-0.625, 0.625));
    }
    for (int x = 0; x < 4; ++x) {
        for (int y = 0; y < 4; ++y) {
            for (int z = 0; z < 4; ++z) {
                points.emplace_back(-0.5 + x * cutoff, -0.5 + y * cutoff, -0.5 + z * cutoff);
            }
        }
    }
    const std::vector<double> edge{-0.625, -0.625 + cutoff, 0.625 - cutoff, 0.625 - 2 * cutoff};
    for (const double x : edge) {
        for (const double z : edge) {
            points.emplace_back(x, 0.5, z);
        }
    }
    return points;
}

PairSet brute_pairs(const std::vector<Vec3>& points, double cutoff, const NeighbourBox& box) {
    PairSet pairs;
    for (std::size_t i = 0; i < points.size(); ++i) {
        for (std::size_t j = i + 1; j < points.size(); ++j) {
            if (box.distance2(points[i], points[j]) <= cutoff * cutoff) {
                pairs.insert({i, j});
            }
        }
    }
    return pairs;
}

std::vector<Neighbour> brute_within(const std::vector<Vec3>& points, const Vec3& p, double radius,
                                    const NeighbourBox& box) {
    std::vector<Neighbour> found;
    for (std::size_t j = 0; j < points.size(); ++j) {
        const double d2 = box.distance2(p, points[j]);
        if (d2 <= radius * radius) {
            found.push_back({j, d2});
        }
    }
    return found;
}

std::vector<Neighbour> brute_nearest(const std::vector<Vec3>& points, const Vec3& p, std::size_t k,
                                     const NeighbourBox& box) {
    std::vector<Neighbour> all = brute_within(points, p, INFINITY, box);
    std::sort(all.begin(), all.end(), nearer);
    all.resize(std::min(k, all.size()));
    return all;
}

struct CellGridQuery {
    static CellGrid make(const std::vector<Vec3>& points, double cutoff, const NeighbourBox& box) {
        return CellGrid(points, cutoff, box);
    }
};

struct KdTreeQuery {
    static metrics::NeighbourIndex make(const std::vector<Vec3>& points, double,
                                        const NeighbourBox& box) {
        return metrics::NeighbourIndex(points, box);
    }
};

using Queries = boost::mpl::list<CellGridQuery, KdTreeQuery>;

}  // namespace

BOOST_AUTO_TEST_SUITE(neighbour_implementations)

BOOST_AUTO_TEST_CASE_TEMPLATE(queries_equal_brute_force_open_and_periodic, Make, Queries) {
    for (const NeighbourBox& box : {NeighbourBox::open(), periodic_box()}) {
        for (const double cutoff : {0.0625, 0.125, 0.25}) {
            for (std::uint64_t seed = 1; seed <= 3; ++seed) {
                const std::vector<Vec3> points = test_points(seed, 500, cutoff);
                const auto query = Make::make(points, cutoff, box);
                BOOST_TEST_REQUIRE(query.size() == points.size());
                PairSet pairs;
                query.for_each_pair_within(cutoff, [&](std::size_t i, std::size_t j, double d2) {
                    BOOST_TEST(i < j);
                    BOOST_TEST(d2 == box.distance2(points[i], points[j]));
                    BOOST_TEST(pairs.insert({i, j}).second, "pair met twice");
                });
                const PairSet expected = brute_pairs(points, cutoff, box);
                BOOST_TEST_REQUIRE((pairs == expected),
                                   "cutoff " << cutoff << " periodic " << box.periodic);
                BOOST_TEST_REQUIRE(expected.size() >= 144u);  // the inner lattice's alone
            }
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(radius_and_k_queries_equal_brute_force, Make, Queries) {
    Random random(11);
    for (const NeighbourBox& box : {NeighbourBox::open(), periodic_box()}) {
        const std::vector<Vec3> points = test_points(7, 600, 0.125);
        for (const double reach : {0.1, 0.7}) {  // 0.7: one cell across a period
            const auto query = Make::make(points, reach, box);
            for (int q = 0; q < 60; ++q) {
                // Query points inside the cell, on lattice points, and a period or more out.
                Vec3 p(random.uniform(-0.7, 0.7), random.uniform(-0.7, 0.7),
                       random.uniform(-0.7, 0.7));
                if (q % 4 == 1) {
                    p = points[600 + static_cast<std::size_t>(q) % 80];
                } else if (q % 4 == 2) {
                    p += Vec3(2.5, 0.0, -1.25);
                }
                // Radii up to beyond half the period: every point at most once, nearest image.
                for (const double radius : {0.0, 0.125, 0.3, 0.8}) {
                    std::vector<Neighbour> found;
                    query.for_each_within(p, radius, [&](std::size_t j, double d2) {
                        found.push_back({j, d2});
                    });
                    std::sort(found.begin(), found.end(), nearer);
                    std::vector<Neighbour> expected = brute_within(points, p, radius, box);
                    std::sort(expected.begin(), expected.end(), nearer);
                    BOOST_TEST_REQUIRE((found == expected), "query " << q << " radius " << radius
                                                                     << " periodic "
                                                                     << box.periodic);
                }
                for (const std::size_t k : {std::size_t{0}, std::size_t{1}, std::size_t{6},
                                            std::size_t{50}, points.size() + 3}) {
                    BOOST_TEST_REQUIRE((query.nearest(p, k) == brute_nearest(points, p, k, box)),
                                       "query " << q << " k " << k << " periodic " << box.periodic);
                }
            }
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(empty_sets_answer_nothing, Make, Queries) {
    const std::vector<Vec3> none;
    for (const NeighbourBox& box : {NeighbourBox::open(), periodic_box()}) {
        const auto query = Make::make(none, 0.1, box);
        BOOST_TEST(query.nearest(Vec3::Zero(), 3).empty());
        std::size_t met = 0;
        query.for_each_within(Vec3::Zero(), INFINITY, [&](std::size_t, double) { ++met; });
        query.for_each_pair_within(1.0, [&](std::size_t, std::size_t, double) { ++met; });
        BOOST_TEST(met == 0u);
    }
}

BOOST_AUTO_TEST_CASE(settled_grid_finds_the_brute_force_pairs) {
    // The engine's incremental grid stores coordinates only; each stored sphere's index is
    // found by its centre (the generated points are distinct).
    for (const double cutoff : {0.0625, 0.125, 0.25}) {
        const std::vector<Vec3> points = test_points(5, 500, cutoff);
        engine::SettledGrid grid(Container{}, cutoff);
        for (const Vec3& p : points) {
            grid.insert(engine::Sphere{p.x(), p.y(), p.z(), 0.0});
        }
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
        BOOST_TEST((pairs == brute_pairs(points, cutoff, NeighbourBox::open())));
    }
}

BOOST_AUTO_TEST_CASE(settled_grid_with_images_finds_the_periodic_pairs) {
    // With periodic sides the protocol inserts each settled sphere's images one period away
    // (periodic_image_centers) into the grid, whose edge cells keep the points beyond the
    // faces: a box scan then meets every minimum-image neighbour (a pair exactly at the
    // cutoff through a face from one side: the images reach only strictly within it).
    const Container sides = periodic_sides();
    for (const double cutoff : {0.0625, 0.125, 0.25}) {
        const std::vector<Vec3> points = test_points(8, 500, cutoff);
        engine::SettledGrid grid(sides, cutoff);
        std::map<std::tuple<double, double, double>, std::size_t> source;
        for (std::size_t j = 0; j < points.size(); ++j) {
            std::vector<Vec3> copies{points[j]};
            for (const Vec3& image : periodic_image_centers(points[j], sides, cutoff)) {
                copies.push_back(image);
            }
            for (const Vec3& q : copies) {
                grid.insert(engine::Sphere{q.x(), q.y(), q.z(), 0.0});
                source[{q.x(), q.y(), q.z()}] = j;
            }
        }
        PairSet pairs;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const Vec3 span = Vec3::Constant(cutoff);
            grid.for_each_in_box(points[i] - span, points[i] + span, [&](const engine::Sphere& s) {
                const Vec3 q(s.x, s.y, s.z);
                const std::size_t j = source.at({s.x, s.y, s.z});
                if (j != i && (q - points[i]).squaredNorm() <= cutoff * cutoff) {
                    pairs.insert({std::min(i, j), std::max(i, j)});
                }
            });
        }
        BOOST_TEST((pairs == brute_pairs(points, cutoff, periodic_box())), "cutoff " << cutoff);
    }
}

BOOST_AUTO_TEST_CASE(pair_columns_with_images_find_the_periodic_pairs) {
    // The metrics' pair passes see a periodic pack as its particles and their images within
    // the reach of a face (with_periodic_images): the windows of the pair columns
    // around each particle then hold every minimum-image neighbour.
    const Container sides = periodic_sides();
    for (const double cutoff : {0.0625, 0.125, 0.25}) {
        const std::vector<Vec3> points = test_points(9, 500, cutoff);
        std::vector<Particle> particles(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            particles[i].center = points[i];
        }
        const ImagedParticles imaged = with_periodic_images(particles, sides, cutoff);
        const metrics::PairColumns columns(imaged.particles, 0.1, 1);
        PairSet pairs;
        for (std::size_t c = 0; c < columns.columns(); ++c) {
            for (std::size_t p = columns.column_begin(c); p < columns.column_begin(c + 1); ++p) {
                const std::size_t i = columns.index[p];
                if (i >= imaged.originals) {
                    continue;
                }
                const Vec3& a = imaged.particles[i].center;
                columns.for_each_column(
                    {a.x(), a.x(), a.y(), a.y()}, cutoff, 0,
                    [&](std::size_t, std::size_t first, std::size_t last, double half) {
                        for (std::size_t k = first; k < last; ++k) {
                            const Vec3 q(columns.x[k], columns.y[k], columns.z[k]);
                            const std::size_t j = imaged.source[columns.index[k]];
                            if (std::abs(q.z() - a.z()) <= half && j != i &&
                                (q - a).squaredNorm() <= cutoff * cutoff) {
                                pairs.insert({std::min(i, j), std::max(i, j)});
                            }
                        }
                    });
            }
        }
        BOOST_TEST((pairs == brute_pairs(points, cutoff, periodic_box())), "cutoff " << cutoff);
    }
}

BOOST_AUTO_TEST_CASE(verlet_list_finds_the_brute_force_pairs_open_and_periodic) {
    // Balls of radius 0 and a skin of the cutoff: the list's pairs are those within it
    // (strictly: a Verlet list keeps gaps below its skin).
    Container walls;
    Container periodic = walls;
    periodic.periodic = true;
    for (const Container& sides : {walls, periodic}) {
        const std::vector<Vec3> points = test_points(6, 1500, 0.125);
        std::vector<engine::Ball> balls;
        for (const Vec3& p : points) {
            balls.push_back({p.x(), p.y(), p.z(), 0.0});
        }
        const double skin = 0.1;
        engine::NeighbourList list;
        list.build(balls, skin, sides);
        PairSet pairs;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const auto near = list.of(i);
            // The list's order is the pairs' (i, j) order, whatever the grid.
            BOOST_TEST(std::is_sorted(near.begin(), near.end()), "sphere " << i);
            for (const std::uint32_t j : near) {
                pairs.insert({i, j});
            }
        }
        PairSet expected;
        const NeighbourBox box = NeighbourBox::of(sides);
        for (std::size_t i = 0; i < points.size(); ++i) {
            for (std::size_t j = i + 1; j < points.size(); ++j) {
                if (box.distance2(points[i], points[j]) < skin * skin) {
                    expected.insert({i, j});
                }
            }
        }
        BOOST_TEST((pairs == expected), "periodic " << sides.periodic);
        BOOST_TEST(expected.size() > 1000u);
    }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_CASE(cell_grid_queries_from_above_the_top_layer_and_with_negative_radii) {
    // A review's reproducers. A query from above the centres meets the top layer's centres
    // at exactly its radius (the lowest layer of the query is clamped to the top layer, as
    // in the counting-sort grid this one replaced); a negative radius meets nothing, also
    // in a periodic box (its unwrapped cell range is empty, not the whole period).
    std::vector<Vec3> centers{Vec3(0, 0, 0), Vec3(0, 1.0 - std::ldexp(1.0, -53), 0)};
    for (int i = 0; i < 40; ++i) {
        centers.emplace_back(0.01 * i, 0.5, 0.3);
    }
    const CellGrid open(centers, 1.0);
    std::vector<std::size_t> met;
    open.for_each_near(Vec3(0, 5, 0), 4.0, [&](std::size_t j, double) { met.push_back(j); });
    BOOST_TEST(met == std::vector<std::size_t>{1});
    NeighbourBox box;
    box.periodic = true;
    box.x_max = 10.0;
    box.z_max = 10.0;
    const CellGrid periodic(std::vector<Vec3>{Vec3(0.5, 0.5, 5.1)}, 1.0, box);
    std::size_t count = 0;
    periodic.for_each_near(Vec3(0.5, 0.5, 5.1), -0.3, [&](std::size_t, double) { ++count; });
    BOOST_TEST(count == 0u);
}
