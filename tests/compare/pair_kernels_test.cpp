// The vector kernels of the pair passes (pair_kernels.hpp: AVX-512 where the CPU has it,
// else AVX2) against their scalar loops, which they must match exactly: the same g(r) bins
// and split counts, the same pairs within a limit in the same order, and the same results
// of the whole passes (measure_local_structure, measure_overlaps) bit for bit. Candidates
// are put on the edges where rounding decides: distances at bin edges (k ± ½)·ΔR, at the
// reach and at the split windows' ends, coincident centres, and windows of every length
// 0–19 (the vector groups' tails). On a CPU with neither, both sides run the scalar loops.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <tuple>

#include "sgmp/metrics/local_structure.hpp"
#include "sgmp/metrics/overlaps.hpp"
#include "sgmp/metrics/pair_kernels.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;
using namespace sgmp::metrics;

namespace {

/// Switches the vector kernels off for its lifetime.
struct ScalarOnly {
    ScalarOnly() { enable_vector_kernels(false); }
    ~ScalarOnly() { enable_vector_kernels(true); }
    ScalarOnly(const ScalarOnly&) = delete;
    ScalarOnly& operator=(const ScalarOnly&) = delete;
};

/// A whole number in [lo, hi], uniform.
int pick(Random& random, int lo, int hi) {
    const int k = lo + static_cast<int>(random.uniform01() * static_cast<double>(hi - lo + 1));
    return std::min(k, hi);
}

struct Window {
    std::vector<double> x, y, z;
};

/// `n` candidates around a = (0.1, −0.2, 0.3): random directions at distances from a mix
/// of random values and values on the edges (bin edges, reach, split windows, 0).
Window edge_window(Random& random, std::size_t n, const BinSetup& s, double width) {
    Window w;
    const double a[3] = {0.1, -0.2, 0.3};
    for (std::size_t k = 0; k < n; ++k) {
        double r = 0.0;
        switch (pick(random, 0, 5)) {
            case 0:
                r = random.uniform(0.0, 1.1 * std::sqrt(s.reach_squared));
                break;
            case 1:  // a bin edge, or one ulp either side
                r = (static_cast<double>(pick(random, 0, static_cast<int>(s.bins))) + 0.5) * width;
                r = pick(random, 0, 2) == 0 ? std::nextafter(r, 0.0) : r;
                break;
            case 2:
                r = std::sqrt(s.reach_squared);
                break;
            case 3: {
                const int e = pick(random, 0, 3);
                r = e < 2 ? s.split_lo[e] : s.split_hi[e - 2];
                break;
            }
            case 4:
                r = 0.0;  // a coincident centre
                break;
            default:
                r = random.uniform(0.9, 1.1) * 2.0 * width * 50.0;
        }
        // A direction along an axis keeps r exact; otherwise random.
        Vec3 u(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0));
        if (pick(random, 0, 1) == 0 || u.norm() == 0.0) {
            u = Vec3::Zero();
            u[pick(random, 0, 2)] = 1.0;
        } else {
            u /= u.norm();
        }
        w.x.push_back(a[0] + r * u.x());
        w.y.push_back(a[1] + r * u.y());
        w.z.push_back(a[2] + r * u.z());
    }
    return w;
}

BinSetup bin_setup(double d, std::size_t bins) {
    const double width = 0.02 * d;
    BinSetup s{};
    s.per_width = 1.0 / width;
    s.bins = static_cast<std::uint32_t>(bins);
    const double reach = (static_cast<double>(bins) - 0.5) * width;
    s.reach_squared = reach * reach;
    for (int w = 0; w < 2; ++w) {
        const double center = w == 0 ? kSplitLow : kSplitHigh;
        s.split_lo[w] = (center - kSplitWindowHalfWidth) * d;
        s.split_hi[w] = (center + kSplitWindowHalfWidth) * d;
    }
    s.split_first = static_cast<std::uint32_t>(bin_of(s.split_lo[0], s.per_width) - 1);
    s.split_bins =
        static_cast<std::uint32_t>(bin_of(s.split_hi[1], s.per_width) + 1 - s.split_first);
    return s;
}

/// The lane histograms summed, dump bin left out.
std::vector<std::int64_t> totals(const std::vector<std::int64_t>& lanes, std::size_t bins) {
    std::vector<std::int64_t> t(bins, 0);
    for (std::size_t l = 0; l < kBinLanes; ++l) {
        for (std::size_t b = 0; b < bins; ++b) {
            t[b] += lanes[l * (bins + 1) + b];
        }
    }
    return t;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pair_kernels)

BOOST_AUTO_TEST_CASE(bins_match_the_scalar_loop_on_edges_and_tails) {
    Random random(11);
    for (const auto& [d, bins] :
         {std::tuple{0.01, std::size_t{251}}, std::tuple{1.0, std::size_t{251}},
          std::tuple{0.037, std::size_t{40}}, std::tuple{0.5, std::size_t{3000}}}) {
        const BinSetup s = bin_setup(d, bins);
        for (std::size_t n = 0; n < 20; ++n) {
            for (int repeat = 0; repeat < 30; ++repeat) {
                const Window w = edge_window(random, n + 3, s, 0.02 * d);
                const double a[3] = {0.1, -0.2, 0.3};
                std::vector<std::int64_t> fast(kBinLanes * (bins + 1), 0);
                std::vector<std::int64_t> slow(fast.size(), 0);
                std::int64_t fast_split[2] = {0, 0};
                std::int64_t slow_split[2] = {0, 0};
                count_bins(w.x.data(), w.y.data(), w.z.data(), a, 3, n + 3, 2, s, fast.data(),
                           fast_split);
                count_bins_scalar(w.x.data(), w.y.data(), w.z.data(), a, 3, n + 3, 2, s,
                                  slow.data(), slow_split);
                BOOST_TEST(totals(fast, bins) == totals(slow, bins),
                           boost::test_tools::per_element());
                BOOST_TEST(fast_split[0] == slow_split[0]);
                BOOST_TEST(fast_split[1] == slow_split[1]);
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(column_windows_and_pairs_match_the_scalar_loops) {
    // Two columns sorted by z with gaps (runs of empty windows), repeated z values, and
    // both the own-column (pairs after p only) and the other-column case.
    Random random(12);
    const BinSetup s = bin_setup(0.05, 251);
    for (int repeat = 0; repeat < 40; ++repeat) {
        Window o;
        Window t;
        for (Window* w : {&o, &t}) {
            const int n = pick(random, 0, 60);
            for (int k = 0; k < n; ++k) {
                const double gap = pick(random, 0, 9) == 0 ? 2.0 : 0.0;
                const double z = (pick(random, 0, 4) == 0 && !w->z.empty())
                                     ? w->z.back()
                                     : random.uniform(-0.3, 0.3) + gap;
                w->x.push_back(random.uniform(0.0, 0.08));
                w->y.push_back(random.uniform(0.0, 0.08));
                w->z.push_back(z);
            }
            std::sort(w->z.begin(), w->z.end());
        }
        const double half = random.uniform(0.01, 0.3);
        for (const bool own : {false, true}) {
            const Window& target = own ? o : t;
            std::vector<std::int64_t> fast(kBinLanes * (251 + 1), 0);
            std::vector<std::int64_t> slow(fast.size(), 0);
            std::int64_t fast_split[2] = {0, 0};
            std::int64_t slow_split[2] = {0, 0};
            count_column_bins(o.x.data(), o.y.data(), o.z.data(), 0, o.z.size(), target.x.data(),
                              target.y.data(), target.z.data(), 0, target.z.size(), half, own, 1, s,
                              fast.data(), fast_split);
            std::vector<std::tuple<std::size_t, std::size_t, double>> fast_pairs;
            std::vector<std::tuple<std::size_t, std::size_t, double>> slow_pairs;
            const auto run_pairs = [&](auto& out) {
                for_each_pair_within(
                    o.x.data(), o.y.data(), o.z.data(), 0, o.z.size(), target.x.data(),
                    target.y.data(), target.z.data(), 0, target.z.size(), half, own, 0.01,
                    [&](std::size_t p, std::size_t k, double q) { out.emplace_back(p, k, q); });
            };
            run_pairs(fast_pairs);
            {
                const ScalarOnly scalar;
                count_column_bins(o.x.data(), o.y.data(), o.z.data(), 0, o.z.size(),
                                  target.x.data(), target.y.data(), target.z.data(), 0,
                                  target.z.size(), half, own, 1, s, slow.data(), slow_split);
                run_pairs(slow_pairs);
            }
            BOOST_TEST(totals(fast, 251) == totals(slow, 251), boost::test_tools::per_element());
            BOOST_TEST(fast_split[0] == slow_split[0]);
            BOOST_TEST(fast_split[1] == slow_split[1]);
            BOOST_TEST((fast_pairs == slow_pairs));
        }
    }
}

BOOST_AUTO_TEST_CASE(passes_are_bit_identical_with_and_without_vectors) {
    for (const auto& [seed, count, r, spread] :
         {std::tuple{21ULL, 3000UL, 0.02, 0.0}, std::tuple{22ULL, 2000UL, 0.025, 0.6}}) {
        Random random(seed);
        std::vector<Particle> particles(count);
        std::vector<Index> origins;
        double diameter_sum = 0.0;
        for (std::size_t i = 0; i < count; ++i) {
            Particle& p = particles[i];
            p.id = static_cast<std::int64_t>(count - i);
            p.radius = r * (1.0 + spread * random.uniform(0.0, 1.0));
            p.center = Vec3(random.uniform(-0.6, 0.6), random.uniform(-0.6, 0.4),
                            random.uniform(-0.6, 0.6));
            diameter_sum += 2.0 * p.radius;
            if (std::abs(p.center.x()) <= 0.35 && std::abs(p.center.z()) <= 0.35) {
                origins.push_back(static_cast<Index>(i));
            }
        }
        LocalStructureOptions o;
        o.tolerances = {0.0, 1e-3, 2e-2, 5e-2, 0.2};
        o.mean_diameter = diameter_sum / static_cast<double>(count);
        o.bins = bins_for(5.0 / 0.02);
        o.space = Box{Vec3(-0.6, -0.6, -0.6), Vec3(0.6, 0.4, 0.6)};
        const LocalStructure fast = measure_local_structure(particles, origins, o);
        const OverlapStats fast_overlaps =
            measure_overlaps(particles, Container{}, o.mean_diameter, 1e-9, 10);
        LocalStructure slow;
        OverlapStats slow_overlaps;
        {
            const ScalarOnly scalar;
            slow = measure_local_structure(particles, origins, o);
            slow_overlaps = measure_overlaps(particles, Container{}, o.mean_diameter, 1e-9, 10);
        }
        BOOST_TEST(fast.rdf.pairs == slow.rdf.pairs, boost::test_tools::per_element());
        BOOST_TEST(fast.rdf.split_pairs[0] == slow.rdf.split_pairs[0]);
        BOOST_TEST(fast.rdf.split_pairs[1] == slow.rdf.split_pairs[1]);
        BOOST_TEST(fast.rdf.g == slow.rdf.g, boost::test_tools::per_element());
        BOOST_TEST(fast.coordination.z_mean == slow.coordination.z_mean,
                   boost::test_tools::per_element());
        for (std::size_t t = 0; t < o.tolerances.size(); ++t) {
            BOOST_TEST(fast.coordination.p_z[t] == slow.coordination.p_z[t],
                       boost::test_tools::per_element());
        }
        BOOST_TEST(fast.bond_order.q6_global == slow.bond_order.q6_global);  // exact
        BOOST_TEST(fast.bond_order.q6_local_mean == slow.bond_order.q6_local_mean);
        const OverlapSummary& a = fast_overlaps.pairs;
        const OverlapSummary& b = slow_overlaps.pairs;
        BOOST_TEST(a.count_any > 0);
        BOOST_TEST(a.count == b.count);
        BOOST_TEST(a.count_any == b.count_any);
        BOOST_TEST(a.max_over_d == b.max_over_d);
        BOOST_TEST(a.mean_over_d == b.mean_over_d);  // the same sum in the same order
        BOOST_REQUIRE_EQUAL(a.worst.size(), b.worst.size());
        for (std::size_t k = 0; k < a.worst.size(); ++k) {
            BOOST_TEST(a.worst[k].id_a == b.worst[k].id_a);
            BOOST_TEST(a.worst[k].id_b == b.worst[k].id_b);
            BOOST_TEST(a.worst[k].depth_over_d == b.worst[k].depth_over_d);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
