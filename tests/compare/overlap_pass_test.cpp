// The parallel overlap pass of the metrics (whole-column grid, pairs once from their
// earlier member) against a brute-force O(N²) loop over every pair: the counts, the
// deepest depth and the ten deepest pairs must agree exactly (the same depth expression);
// the mean depth sums the same terms in another order, so it agrees to 1e-12 relative
// (≤ 10⁴ terms, each rounded to 1e-16). For one and two threads every value is identical.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "sgmp/metrics/overlaps.hpp"
#include "sgmp/metrics/parallel.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;
using namespace sgmp::metrics;

namespace {

/// `count` spheres at random in a box of 1.2 × 1.0 × 1.2 (overlaps likely), radii r to
/// r·(1 + spread), ids in reverse order of index.
std::vector<Particle> random_spheres(std::uint64_t seed, std::size_t count, double r,
                                     double spread) {
    Random random(seed);
    std::vector<Particle> particles(count);
    for (std::size_t i = 0; i < count; ++i) {
        Particle& p = particles[i];
        p.id = static_cast<std::int64_t>(count - i);
        p.radius = r * (1.0 + spread * random.uniform(0.0, 1.0));
        p.center =
            Vec3(random.uniform(-0.6, 0.6), random.uniform(-0.6, 0.4), random.uniform(-0.6, 0.6));
    }
    return particles;
}

struct Brute {
    std::int64_t count = 0;
    std::int64_t count_any = 0;
    double max = 0.0;
    double sum = 0.0;
    std::vector<OverlapRecord> all;
};

Brute brute_force(const std::vector<Particle>& particles, double d, double floor) {
    Brute b;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        for (std::size_t j = i + 1; j < particles.size(); ++j) {
            const Particle& p = particles[i];
            const Particle& q = particles[j];
            const double depth = p.radius + q.radius - (p.center - q.center).norm();
            if (depth > 0.0) {
                ++b.count_any;
                b.max = std::max(b.max, depth / d);
                if (depth / d > floor) {
                    ++b.count;
                    b.sum += depth / d;
                }
                b.all.push_back({std::min(p.id, q.id), std::max(p.id, q.id), depth / d});
            }
        }
    }
    std::sort(b.all.begin(), b.all.end(), [](const OverlapRecord& u, const OverlapRecord& v) {
        if (u.depth_over_d != v.depth_over_d) {
            return u.depth_over_d > v.depth_over_d;
        }
        return u.id_a != v.id_a ? u.id_a < v.id_a : u.id_b < v.id_b;
    });
    return b;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(overlap_pass)

BOOST_AUTO_TEST_CASE(pairs_match_brute_force) {
    const Container container;
    for (const auto& [seed, count, r, spread] :
         {std::tuple{1ULL, 1500UL, 0.02, 0.0}, std::tuple{2ULL, 2000UL, 0.01, 1.0},
          std::tuple{3ULL, 800UL, 0.05, 0.3}}) {
        const auto particles = random_spheres(seed, count, r, spread);
        const double d = 2.0 * r;
        const double floor = 1e-3;
        const Brute expected = brute_force(particles, d, floor);
        BOOST_REQUIRE_GT(expected.count, 20);  // the case has overlaps to find
        const OverlapStats got = measure_overlaps(particles, container, d, floor, 10);
        BOOST_TEST(got.pairs.count == expected.count);
        BOOST_TEST(got.pairs.count_any == expected.count_any);
        BOOST_TEST(got.pairs.max_over_d == expected.max);
        BOOST_TEST(std::abs(got.pairs.mean_over_d * static_cast<double>(expected.count) -
                            expected.sum) <= 1e-12 * expected.sum);
        BOOST_REQUIRE_EQUAL(got.pairs.worst.size(), 10U);
        for (std::size_t k = 0; k < 10; ++k) {
            BOOST_TEST(got.pairs.worst[k].id_a == expected.all[k].id_a);
            BOOST_TEST(got.pairs.worst[k].id_b == expected.all[k].id_b);
            BOOST_TEST(got.pairs.worst[k].depth_over_d == expected.all[k].depth_over_d);
        }
    }
}

BOOST_AUTO_TEST_CASE(results_are_bit_identical_for_any_thread_count) {
    const auto particles = random_spheres(4, 20000, 0.006, 0.5);
    const Container container;
    const OverlapStats one = measure_overlaps(particles, container, 0.012, 1e-9, 10, 1);
    const OverlapStats two = measure_overlaps(particles, container, 0.012, 1e-9, 10, 2);
    BOOST_TEST(one.pairs.count > 1000);
    BOOST_TEST(one.pairs.count == two.pairs.count);
    BOOST_TEST(one.pairs.mean_over_d == two.pairs.mean_over_d);  // exact, not close
    BOOST_TEST(one.pairs.max_over_d == two.pairs.max_over_d);
    BOOST_TEST(one.walls.count == two.walls.count);
    BOOST_TEST(one.walls.mean_over_d == two.walls.mean_over_d);
}

BOOST_AUTO_TEST_SUITE_END()
