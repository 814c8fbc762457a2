// The fused pair pass of measure_local_structure (pair columns, one loop for g(r), Z(δ) and
// Q6) against a brute-force O(N²) loop over every pair, on a few hundred spheres.
// Pair, contact and wall counts are integers and must agree exactly; Q6 sums the same
// bonds in another order, so it agrees to rounding: 1e-12 (the sums hold ~10³ terms of
// size ≤ 1, each rounded to 1e-16).
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "sgmp/metrics/bond_order.hpp"
#include "sgmp/metrics/local_structure.hpp"
#include "sgmp/metrics/pair_columns.hpp"
#include "sgmp/metrics/parallel.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;
using namespace sgmp::metrics;

namespace {

struct Case {
    std::vector<Particle> particles;
    std::vector<Index> origins;
    LocalStructureOptions options;
};

/// `count` spheres at random in the container (overlaps allowed: they only add contacts),
/// radii from r to r·(1 + spread); origins are the centres in the box |x|, |z| ≤ 0.3.
Case random_case(std::uint64_t seed, std::size_t count, double r, double spread) {
    Case c;
    Random random(seed);
    double diameter_sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        Particle p;
        p.id = static_cast<std::int64_t>(i);
        p.radius = r * (1.0 + spread * random.uniform(0.0, 1.0));
        p.center =
            Vec3(random.uniform(-0.6, 0.6), random.uniform(-0.6, 0.4), random.uniform(-0.6, 0.6));
        diameter_sum += 2.0 * p.radius;
        c.particles.push_back(p);
    }
    for (Index i = 0; i < count; ++i) {
        const Vec3& x = c.particles[i].center;
        if (std::abs(x.x()) <= 0.3 && std::abs(x.z()) <= 0.3) {
            c.origins.push_back(i);
        }
    }
    LocalStructureOptions& o = c.options;
    o.tolerances = {0.0, 1e-3, 2e-2, 5e-2, 0.2};
    o.mean_diameter = diameter_sum / static_cast<double>(count);
    o.bin_width_over_d = 0.02;
    o.bins = bins_for(5.0 / 0.02);
    o.q6_cutoff = 1.2;
    o.space = Box{Vec3(-0.6, -0.6, -0.6), Vec3(0.6, 0.4, 0.6)};
    return c;
}

struct Counts {
    std::vector<std::int64_t> pairs;
    std::vector<double> z_sum;
    std::int64_t split_pairs[2] = {0, 0};
    double q6_global = 0.0;
    double q6_local_mean = 0.0;
};

Counts brute_force(const Case& c) {
    const LocalStructureOptions& o = c.options;
    const double d = o.mean_diameter;
    const double per_width = 1.0 / (o.bin_width_over_d * d);
    Counts n;
    n.pairs.assign(o.bins, 0);
    n.z_sum.assign(o.tolerances.size(), 0.0);
    BondSums global;
    double local = 0.0;
    std::int64_t with_bonds = 0;
    for (const Index i : c.origins) {
        const Particle& a = c.particles[i];
        BondSums bonds;
        for (Index j = 0; j < c.particles.size(); ++j) {
            if (j == i) {
                continue;
            }
            const Particle& b = c.particles[j];
            const Vec3 v = b.center - a.center;
            const double distance = std::sqrt(v.x() * v.x() + v.y() * v.y() + v.z() * v.z());
            const auto bin = bin_of(distance, per_width);
            if (bin < o.bins) {
                ++n.pairs[bin];
            }
            const double centers[2] = {kSplitLow, kSplitHigh};
            for (int w = 0; w < 2; ++w) {
                n.split_pairs[w] +=
                    std::abs(distance - centers[w] * d) <= kSplitWindowHalfWidth * d;
            }
            for (std::size_t t = 0; t < o.tolerances.size(); ++t) {
                n.z_sum[t] += distance - a.radius - b.radius <= o.tolerances[t] * d ? 1 : 0;
            }
            if (distance <= o.q6_cutoff * (a.radius + b.radius)) {
                bonds.add(v / distance);
            }
        }
        if (bonds.bonds > 0) {
            global.add(bonds);
            local += bonds.q6();
            ++with_bonds;
        }
    }
    n.q6_global = global.q6();
    n.q6_local_mean = local / static_cast<double>(with_bonds);
    return n;
}

LocalStructure fast(const Case& c, unsigned threads = 0) {
    LocalStructureOptions options = c.options;
    options.threads = threads;
    return measure_local_structure(c.particles, c.origins, options);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(local_structure)

BOOST_AUTO_TEST_CASE(fused_pass_matches_brute_force) {
    // Mono- and polydisperse; radii large enough that 5·d spans much of the box (edge
    // correction exercised) and many spheres touch.
    for (const auto& [seed, count, r, spread] :
         {std::tuple{1ULL, 300UL, 0.04, 0.0}, std::tuple{2ULL, 500UL, 0.03, 0.5},
          std::tuple{3ULL, 400UL, 0.05, 1.0}}) {
        const Case c = random_case(seed, count, r, spread);
        BOOST_REQUIRE_GT(c.origins.size(), 20U);
        const Counts expected = brute_force(c);
        const LocalStructure got = fast(c);
        BOOST_TEST(got.rdf.pairs == expected.pairs, boost::test_tools::per_element());
        BOOST_TEST(got.rdf.split_pairs[0] == expected.split_pairs[0]);
        BOOST_TEST(got.rdf.split_pairs[1] == expected.split_pairs[1]);
        std::int64_t contacts = 0;
        for (std::size_t t = 0; t < c.options.tolerances.size(); ++t) {
            const double z_sum = got.coordination.z_mean[t] * static_cast<double>(c.origins.size());
            BOOST_TEST(std::llround(z_sum) == std::llround(expected.z_sum[t]));
            contacts += std::llround(expected.z_sum[t]);
        }
        BOOST_TEST(contacts > 0);  // the case has contacts to count
        BOOST_TEST(std::abs(got.bond_order.q6_global - expected.q6_global) <= 1e-12);
        BOOST_TEST(std::abs(got.bond_order.q6_local_mean - expected.q6_local_mean) <= 1e-12);
    }
}

BOOST_AUTO_TEST_CASE(results_are_bit_identical_for_any_thread_count) {
    const Case c = random_case(4, 2000, 0.02, 0.3);
    const LocalStructure one = fast(c, 1);
    const LocalStructure two = fast(c, 2);
    BOOST_TEST(one.rdf.pairs == two.rdf.pairs, boost::test_tools::per_element());
    BOOST_TEST(one.rdf.shell_volume == two.rdf.shell_volume, boost::test_tools::per_element());
    BOOST_TEST(one.coordination.z_mean == two.coordination.z_mean,
               boost::test_tools::per_element());
    BOOST_TEST(one.bond_order.q6_global == two.bond_order.q6_global);  // exact, not close
    BOOST_TEST(one.bond_order.q6_local_mean == two.bond_order.q6_local_mean);
}

BOOST_AUTO_TEST_CASE(pair_columns_partition_the_centres_sorted_by_height) {
    // Every member once, each column sorted by z (then index), for spread, flat, linear
    // and coincident centres, and for no centre at all.
    Random random(7);
    std::vector<std::vector<Particle>> sets(4, std::vector<Particle>(900));
    for (std::size_t i = 0; i < 900; ++i) {
        const double u = random.uniform(-1, 1);
        sets[0][i].center = Vec3(u, random.uniform(0, 0.5), random.uniform(-2, 1));
        sets[1][i].center = Vec3(u, 0.25, random.uniform(-2, 1));        // a plane
        sets[2][i].center = Vec3(u, 0.25, 0.5);                          // a line
        sets[3][i].center = Vec3(0.1, 0.2, static_cast<double>(i % 7));  // one column
    }
    sets.emplace_back();
    for (const auto& particles : sets) {
        for (const double side : {0.01, 0.2, 3.0}) {
            const PairColumns columns(particles, side, 0);
            BOOST_TEST(columns.column_begin(columns.columns()) == particles.size());
            std::vector<int> seen(particles.size(), 0);
            for (std::size_t c = 0; c < columns.columns(); ++c) {
                BOOST_TEST(columns.column_begin(c) < columns.column_begin(c + 1));
                for (std::size_t k = columns.column_begin(c); k < columns.column_begin(c + 1);
                     ++k) {
                    ++seen[columns.index[k]];
                    BOOST_TEST(columns.z[k] == particles[columns.index[k]].center.z());
                    if (k > columns.column_begin(c)) {
                        BOOST_TEST((columns.z[k - 1] < columns.z[k] ||
                                    (columns.z[k - 1] == columns.z[k] &&
                                     columns.index[k - 1] < columns.index[k])));
                    }
                }
            }
            BOOST_TEST(std::count(seen.begin(), seen.end(), 1) ==
                       static_cast<std::ptrdiff_t>(particles.size()));
        }
    }
}

BOOST_AUTO_TEST_CASE(pair_column_windows_hold_every_center_within_the_radius) {
    // For the columns over one set and those over a different
    // set (other column sides): for every source centre p, the windows |z − z_p| ≤ half of
    // the columns met are disjoint and hold every target centre within the radius of p
    // (brute force); with first_column, each pair of columns within reach is met once.
    Random random(8);
    std::vector<Particle> particles(1500);
    for (auto& p : particles) {
        p.center = Vec3(random.uniform(-1, 1), random.uniform(0, 0.5), random.uniform(-2, 1));
    }
    std::vector<Index> sources;
    std::vector<Index> targets;
    for (Index i = 0; i < particles.size(); ++i) {
        (i % 3 == 0 ? sources : targets).push_back(i);
    }
    for (const double side : {0.05, 0.2, 1.0}) {
        const PairColumns source(particles, sources, side, 0);
        const PairColumns target(particles, targets, 0.7 * side, 0);
        for (const double radius : {0.0, 0.07, 0.3}) {
            for (std::size_t c = 0; c < source.columns(); ++c) {
                const std::size_t begin = source.column_begin(c);
                const std::size_t end = source.column_begin(c + 1);
                std::vector<std::vector<int>> seen(end - begin,
                                                   std::vector<int>(particles.size(), 0));
                target.for_each_column(
                    source.footprint(begin, end), radius, 0,
                    [&](std::size_t, std::size_t first, std::size_t last, double half) {
                        for (std::size_t p = begin; p < end; ++p) {
                            for (std::size_t k = first; k < last; ++k) {
                                if (std::abs(target.z[k] - source.z[p]) <= half) {
                                    ++seen[p - begin][target.index[k]];
                                }
                            }
                        }
                    });
                for (std::size_t p = begin; p < end; ++p) {
                    const Vec3& a = particles[source.index[p]].center;
                    for (const Index j : targets) {
                        BOOST_TEST(seen[p - begin][j] <= 1);
                        if ((particles[j].center - a).norm() <= radius) {
                            BOOST_TEST(seen[p - begin][j] == 1);
                        }
                    }
                }
            }
        }
        // Pairs of columns of one tree: met once, from the lower-numbered one.
        const double radius = 0.3;
        std::vector<std::vector<int>> met(source.columns(), std::vector<int>(source.columns(), 0));
        for (std::size_t c = 0; c < source.columns(); ++c) {
            const auto f = source.footprint(source.column_begin(c), source.column_begin(c + 1));
            source.for_each_column(f, radius, c,
                                   [&](std::size_t other, std::size_t, std::size_t, double) {
                                       BOOST_TEST(other >= c);
                                       ++met[std::min(c, other)][std::max(c, other)];
                                   });
        }
        for (std::size_t a = 0; a < source.columns(); ++a) {
            for (std::size_t b = a; b < source.columns(); ++b) {
                BOOST_TEST(met[a][b] <= 1);
            }
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_CASE(pair_columns_far_from_the_origin_meet_a_column_at_exactly_the_radius) {
    // Four centres near x = 4100 in columns of side 1 (a review's reproducer): the gap from
    // column 2's footprint to column 1's is ρ exactly, and the kd-tree query over the
    // footprint centres (each rounded by half an ulp of ~4100) must still meet column 1:
    // a relative widening alone (10⁻¹²·ρ) left it out. The answer is every column with
    // dist(R, F_c) ≤ ρ (brute force over the footprints), for every column and radius.
    std::vector<Particle> particles(4);
    const double xs[4] = {4101.868126628854, 4099.9167798631752, 4101.5803188296977,
                          4102.0019023329887};
    for (int i = 0; i < 4; ++i) {
        particles[static_cast<std::size_t>(i)].center = Vec3(xs[i], 0.0, 0.0);
    }
    const PairColumns columns(particles, 1.0, 1);
    const auto gap = [](const std::array<double, 4>& a, const std::array<double, 4>& b) {
        const double sx = std::max({0.0, b[0] - a[1], a[0] - b[1]});
        const double sy = std::max({0.0, b[2] - a[3], a[2] - b[3]});
        return std::sqrt(sx * sx + sy * sy);
    };
    std::vector<PairColumns::Reach> met;
    for (std::size_t c = 0; c < columns.columns(); ++c) {
        const auto f = columns.footprint(columns.column_begin(c), columns.column_begin(c + 1));
        for (std::size_t d = 0; d < columns.columns(); ++d) {
            const auto g = columns.footprint(columns.column_begin(d), columns.column_begin(d + 1));
            columns.columns_within(f, gap(f, g), 0, met);
            BOOST_TEST(std::any_of(met.begin(), met.end(),
                                   [&](const PairColumns::Reach& r) { return r.column == d; }),
                       "column " << d << " from column " << c);
        }
    }
}
