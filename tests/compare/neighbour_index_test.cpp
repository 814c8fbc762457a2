#include "sgmp/metrics/neighbour_index.hpp"

#include <boost/test/unit_test.hpp>
#include <set>

#include "sgmp/pack/random.hpp"

using namespace sgmp;
using namespace sgmp::metrics;

namespace {

std::set<std::pair<Index, Index>> brute_force(const std::vector<Vec3>& points, double cutoff) {
    std::set<std::pair<Index, Index>> pairs;
    for (Index i = 0; i < points.size(); ++i) {
        for (Index j = i + 1; j < points.size(); ++j) {
            const Vec3 d = points[j] - points[i];
            if (d.x() * d.x() + d.y() * d.y() + d.z() * d.z() <= cutoff * cutoff) {
                pairs.emplace(i, j);
            }
        }
    }
    return pairs;
}

/// Every pair (i, j), i < j, within `cutoff`, in the order the index meets them.
std::vector<std::pair<Index, Index>> pairs_within(const std::vector<Vec3>& points, double cutoff) {
    const NeighbourIndex index(points);
    std::vector<std::pair<Index, Index>> pairs;
    index.for_each_pair_within(cutoff, [&](std::size_t i, std::size_t j, double) {
        pairs.emplace_back(static_cast<Index>(i), static_cast<Index>(j));
    });
    return pairs;
}

std::set<std::pair<Index, Index>> as_set(const std::vector<std::pair<Index, Index>>& pairs) {
    return {pairs.begin(), pairs.end()};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(neighbour_index)

BOOST_AUTO_TEST_CASE(pairs_match_brute_force_on_random_sets) {
    for (const std::uint64_t seed : {1, 2, 3, 4}) {
        Random random(seed);
        std::vector<Vec3> points(1500);
        for (auto& p : points) {
            p = Vec3(random.uniform(-0.5, 0.5), random.uniform(-0.5, 1.0), random.uniform(0, 0.3));
        }
        for (const double cutoff : {0.0, 0.02, 0.07, 0.2}) {
            const auto found = pairs_within(points, cutoff);
            BOOST_TEST(found.size() == as_set(found).size());  // no duplicates
            BOOST_TEST((as_set(found) == brute_force(points, cutoff)),
                       "seed " << seed << " cutoff " << cutoff);
        }
    }
}

BOOST_AUTO_TEST_CASE(points_exactly_on_the_sphere_are_found) {
    // A cubic lattice with spacing 0.125 (exact in binary): neighbours lie exactly at the
    // cutoff, where the fuzzy sphere alone may drop them.
    std::vector<Vec3> points;
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
            for (int k = 0; k < 6; ++k) {
                points.emplace_back(0.125 * i, 0.125 * j, 0.125 * k);
            }
        }
    }
    const auto found = pairs_within(points, 0.125);
    BOOST_TEST(found.size() == 3u * 5u * 36u);  // bonds of a 6x6x6 cubic lattice
    BOOST_TEST((as_set(found) == brute_force(points, 0.125)));
}

BOOST_AUTO_TEST_CASE(within_returns_exactly_the_points_in_the_ball) {
    Random random(9);
    std::vector<Vec3> points(3000);
    for (auto& p : points) {
        p = Vec3(random.uniform01(), random.uniform01(), random.uniform01());
    }
    const NeighbourIndex index(points);
    std::vector<Index> found;
    for (int q = 0; q < 50; ++q) {
        const Vec3 center(random.uniform01(), random.uniform01(), random.uniform01());
        const double radius = random.uniform(0.0, 0.3);
        index.within(center, radius, found);
        std::set<Index> expected;
        for (Index i = 0; i < points.size(); ++i) {
            const Vec3 d = points[i] - center;
            if (d.x() * d.x() + d.y() * d.y() + d.z() * d.z() <= radius * radius) {
                expected.insert(i);
            }
        }
        BOOST_TEST((std::set<Index>(found.begin(), found.end()) == expected));
    }
}

BOOST_AUTO_TEST_SUITE_END()
