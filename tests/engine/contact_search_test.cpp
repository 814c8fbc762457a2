// The grid queries shared by the protocol and the contact models (contact_search.hpp) and
// the pack check (pack_checks.hpp), each against an O(N²) loop written without the grid,
// over random clouds of spheres of two sizes.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "brute_force.hpp"
#include "sgmp/engine/contact_search.hpp"
#include "sgmp/engine/pack_checks.hpp"
#include "sgmp/engine/settled_grid.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

/// `count` spheres of radius 0.04 or 0.07 anywhere in the lower part of the container
/// (overlapping one another and the walls freely).
std::vector<Particle> cloud(std::size_t count, Random& rng) {
    std::vector<Particle> ps;
    for (std::size_t i = 0; i < count; ++i) {
        const double r = rng.uniform01() < 0.5 ? 0.04 : 0.07;
        ps.push_back(Particle{
            static_cast<std::int64_t>(i),
            Vec3(rng.uniform(-0.62, 0.62), rng.uniform(-0.62, 0.1), rng.uniform(-0.62, 0.62)), r,
            0});
    }
    return ps;
}

SettledGrid grid_of(const std::vector<Particle>& ps) {
    SettledGrid grid(Container{}, 0.14);
    for (const Particle& p : ps) {
        grid.insert(Sphere{p.center.x(), p.center.y(), p.center.z(), p.radius});
    }
    return grid;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(contact_search)

// The grid scan stops early (a lower layer cannot beat the best found); the loop looks at
// every sphere. Same formula, so the heights must agree exactly.
BOOST_AUTO_TEST_CASE(first_contact_below_is_the_highest_contact_of_all_spheres) {
    Random rng(11);
    int on_spheres = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const auto ps = cloud(150, rng);
        const SettledGrid grid = grid_of(ps);
        for (int k = 0; k < 20; ++k) {
            const double r = rng.uniform01() < 0.5 ? 0.04 : 0.07;
            const Vec3 c(rng.uniform(-0.58, 0.58), rng.uniform(-0.6, 0.4),
                         rng.uniform(-0.58, 0.58));
            const double margin = k % 2 == 0 ? 0.0 : 1e-9;
            double best = Container{}.floor + r;
            for (const Particle& p : ps) {
                const Sphere s{p.center.x(), p.center.y(), p.center.z(), p.radius};
                best = std::max(best, contact_height(c, r, s, margin));
            }
            const FirstContact hit = first_contact_below(grid, Container{}, 0.07, c, r, margin);
            BOOST_TEST(hit.y == best);
            BOOST_TEST(hit.on_floor == (best == Container{}.floor + r));
            if (!hit.on_floor) {
                ++on_spheres;
                BOOST_TEST(contact_height(c, r, hit.support, margin) == best);
            }
        }
    }
    BOOST_TEST(on_spheres > 300);  // most of the 1200 falls end on a sphere
}

BOOST_AUTO_TEST_CASE(contact_height_of_a_sphere_straight_below_and_beside) {
    const Sphere s{0.0, 0.0, 0.0, 0.05};
    // Straight below: touches at y_s + r + r_s.
    BOOST_TEST(contact_height(Vec3(0.0, 1.0, 0.0), 0.05, s) == 0.1);
    // Offset h = 0.06: y_s + √(0.1² − 0.06²) = 0.08 (to rounding).
    BOOST_TEST(contact_height(Vec3(0.06, 1.0, 0.0), 0.05, s) == 0.08,
               boost::test_tools::tolerance(1e-15));
    // Capped at the start height, outside the column, above the faller, within the margin.
    BOOST_TEST(contact_height(Vec3(0.0, 0.05, 0.0), 0.05, s) == 0.05);
    BOOST_TEST(std::isinf(contact_height(Vec3(0.1, 1.0, 0.0), 0.05, s)));
    BOOST_TEST(std::isinf(contact_height(Vec3(0.0, -0.01, 0.0), 0.05, s)));
    BOOST_TEST(std::isinf(contact_height(Vec3(0.0, 1e-11, 0.0), 0.05, s, 1e-9)));
    BOOST_TEST(!std::isinf(contact_height(Vec3(0.0, 1e-11, 0.0), 0.05, s)));
}

BOOST_AUTO_TEST_CASE(clear_at_agrees_with_every_pair_and_the_walls) {
    Random rng(12);
    int clear = 0;
    int blocked = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const auto ps = cloud(60, rng);
        const SettledGrid grid = grid_of(ps);
        for (int k = 0; k < 50; ++k) {
            const double r = 0.04;
            const Vec3 p(rng.uniform(-0.63, 0.63), rng.uniform(-0.63, 0.3),
                         rng.uniform(-0.63, 0.63));
            bool expected = Container{}.penetration(p, r) <= 1e-12 * r;
            for (const Particle& q : ps) {
                const double D = r + q.radius;
                expected = expected && (p - q.center).norm() - D >= -kRollOverlapTolerance * D;
            }
            BOOST_TEST(clear_at(grid, Container{}, 0.07, p, r) == expected);
            (expected ? clear : blocked) += 1;
        }
    }
    BOOST_TEST(clear > 200);
    BOOST_TEST(blocked > 200);
}

// check_pack's one grid against brute force: pair overlaps, their worst gap (to 1e-15:
// r_i + r_j − |c_i − c_j| and its negation round alike but for the last bit), spheres
// outside, unsupported spheres.
BOOST_AUTO_TEST_CASE(check_pack_counts_what_brute_force_counts) {
    Random rng(13);
    std::size_t overlaps = 0;
    std::size_t unsupported = 0;
    for (int trial = 0; trial < 50; ++trial) {
        const auto ps = cloud(80, rng);
        const double tol = 0.01;
        const double support_tol = 0.02;
        std::size_t pairs = 0;
        for (std::size_t i = 0; i < ps.size(); ++i) {
            for (std::size_t j = i + 1; j < ps.size(); ++j) {
                pairs += (ps[i].center - ps[j].center).norm() - ps[i].radius - ps[j].radius < -tol;
            }
        }
        std::size_t outside = 0;
        std::size_t loose = 0;
        for (std::size_t i = 0; i < ps.size(); ++i) {
            outside += Container{}.penetration(ps[i].center, ps[i].radius) > tol;
            loose += testing::support_distance(ps, i, Container{}) > support_tol;
        }
        const PackCheck check = check_pack(ps, Container{}, tol, support_tol);
        BOOST_TEST(check.overlaps == pairs);
        BOOST_TEST(check.worst_gap == std::min(0.0, testing::worst_pair_gap(ps)),
                   boost::test_tools::tolerance(1e-15));
        BOOST_TEST(check.outside == outside);
        BOOST_TEST(check.unsupported == loose);
        overlaps += pairs;
        unsupported += loose;
    }
    BOOST_TEST(overlaps > 100);
    BOOST_TEST(unsupported > 100);
}

BOOST_AUTO_TEST_SUITE_END()
