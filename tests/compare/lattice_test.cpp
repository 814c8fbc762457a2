// Perfect lattices cut to a box: packing fraction, coordination, g(r) shells and Q6 are
// known in advance.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "sgmp/metrics/measure.hpp"
#include "synthetic_packs.hpp"

using namespace sgmp;
using namespace sgmp::metrics;
using sgmp::testing::Lattice;

namespace {

constexpr double kD = 0.1;

struct Case {
    Lattice lattice;
    double phi;                                  // densest value of the lattice
    double cell;                                 // conventional cube side over d
    int z;                                       // nearest neighbours
    std::vector<std::pair<double, int>> shells;  // (distance over d, count)
};

const std::vector<Case>& cases() {
    static const std::vector<Case> all{
        {Lattice::fcc,
         std::numbers::pi / (3.0 * std::sqrt(2.0)),
         std::sqrt(2.0),
         12,
         {{1.0, 12}, {std::sqrt(2.0), 6}, {std::sqrt(3.0), 24}, {2.0, 12}}},
        {Lattice::bcc,
         std::numbers::pi * std::sqrt(3.0) / 8.0,
         2.0 / std::sqrt(3.0),
         8,
         {{1.0, 8},
          {2.0 / std::sqrt(3.0), 6},
          {std::sqrt(8.0 / 3.0), 12},
          {std::sqrt(11.0 / 3.0), 24}}},
        {Lattice::simple_cubic,
         std::numbers::pi / 6.0,
         1.0,
         6,
         {{1.0, 6}, {std::sqrt(2.0), 12}, {std::sqrt(3.0), 8}, {2.0, 6}}},
    };
    return all;
}

/// The lattice filling [-0.6, 0.6]³, measured in a central cube of 4 conventional cells
/// (any whole number of cells holds exactly the lattice's density, whatever its offset).
Measurement measure_lattice(const Case& c, double bin_width = 0.03) {
    const Box fill{Vec3::Constant(-0.6), Vec3::Constant(0.6)};
    const Pack pack = sgmp::testing::lattice_pack(c.lattice, kD, fill, Vec3::Constant(0.0123));
    const double half = 2.0 * c.cell * kD;
    MeasureOptions options;
    options.region = Box{Vec3::Constant(-half), Vec3::Constant(half)};
    options.gr_bin_width = bin_width;  // shells fall inside bins, away from their edges
    options.gr_range = 2.5;
    return measure(pack, options);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(lattices)

BOOST_AUTO_TEST_CASE(packing_fraction_of_whole_cells) {
    for (const auto& c : cases()) {
        const Measurement m = measure_lattice(c);
        // Exact up to the volume routine's ~1e-13 and summation rounding; 1e-9 is far
        // tighter than the 1e-3 asked of the metric.
        BOOST_TEST(std::abs(m.phi - c.phi) <= 1e-9, "phi " << m.phi << " vs " << c.phi);
    }
}

BOOST_AUTO_TEST_CASE(coordination_at_one_part_per_million) {
    for (const auto& c : cases()) {
        const Measurement m = measure_lattice(c);
        const auto& z = m.local.coordination;
        BOOST_TEST(z.tolerances[1] == 1e-6);
        BOOST_TEST(z.z_mean[1] == c.z);
        BOOST_TEST(z.p_z[1].size() == static_cast<std::size_t>(c.z + 1));
        BOOST_TEST(z.p_z[1][c.z] == 1.0);
        // Touching lattices: 5e-2 adds nothing unless a second shell is that close (none is).
        BOOST_TEST(z.z_mean[5] == c.z);
        BOOST_TEST(m.overlaps.pairs.count == 0);  // rounding-level overlaps stay under the floor
        BOOST_TEST(z.wall_contacts[5] == 0);
    }
}

BOOST_AUTO_TEST_CASE(g_of_r_has_the_shells_at_the_right_distances) {
    for (const auto& c : cases()) {
        const Measurement m = measure_lattice(c);
        const auto& rdf = m.local.rdf;
        const double origins = static_cast<double>(rdf.origins);
        std::vector<bool> expected(rdf.pairs.size(), false);
        for (const auto& [distance, count] : c.shells) {
            const auto bin = bin_of(distance, 1.0 / rdf.bin_width_over_d);
            expected[bin] = true;
            BOOST_TEST(static_cast<double>(rdf.pairs[bin]) / origins == count,
                       "shell at " << distance << " d");
        }
        // Nothing between the shells below the fourth one.
        const double last = c.shells.back().first;
        for (std::size_t k = 0; k < rdf.pairs.size(); ++k) {
            if (!expected[k] && bin_outer(k, rdf.bin_width_over_d) < last) {
                BOOST_TEST(rdf.pairs[k] == 0, "bin " << k);
            }
        }
        // The first peak of g is the contact shell.
        const auto peak = std::max_element(rdf.g.begin(), rdf.g.end()) - rdf.g.begin();
        BOOST_TEST(static_cast<std::size_t>(peak) == bin_of(1.0, 1.0 / rdf.bin_width_over_d));
    }
}

BOOST_AUTO_TEST_CASE(split_ratio_of_the_lattices) {
    // Pairs in the windows |r − √3 d| ≤ 0.05 d and |r − 2 d| ≤ 0.05 d over their volumes
    // 4π/3 [(r0 + a)³ − (r0 − a)³]: FCC has 24 and 12 neighbours there, simple cubic 8 and 6,
    // BCC none at √3 d. Exact up to rounding of the volumes (1e-9 relative).
    const auto volume = [](double r0) {
        const double a = kSplitWindowHalfWidth;
        return std::pow(r0 + a, 3) - std::pow(r0 - a, 3);
    };
    const double fcc = (24.0 / volume(std::sqrt(3.0))) / (12.0 / volume(2.0));
    const double sc = (8.0 / volume(std::sqrt(3.0))) / (6.0 / volume(2.0));
    const std::vector<double> expected{fcc, 0.0, sc};
    for (std::size_t i = 0; i < cases().size(); ++i) {
        const double split = measure_lattice(cases()[i]).local.rdf.split_ratio;
        BOOST_TEST(std::abs(split - expected[i]) <= 1e-9 * std::max(1.0, expected[i]),
                   "lattice " << i << ": " << split << " vs " << expected[i]);
    }
    BOOST_TEST(fcc == 2.6664, boost::test_tools::tolerance(1e-4));
}

BOOST_AUTO_TEST_CASE(q6_of_the_lattices) {
    // Steinhardt values: FCC 0.57452 (12 neighbours), simple cubic 1/(2√2) = 0.35355
    // (6 neighbours), BCC with its 8 + 6 neighbours inside 1.2 d: 0.51069.
    const std::vector<double> expected{0.57452, 0.51069, 0.35355};
    for (std::size_t i = 0; i < cases().size(); ++i) {
        const Measurement m = measure_lattice(cases()[i]);
        BOOST_TEST(std::abs(m.local.bond_order.q6_global - expected[i]) <= 1e-4);
        BOOST_TEST(std::abs(m.local.bond_order.q6_local_mean - expected[i]) <= 1e-4);
    }
}

BOOST_AUTO_TEST_CASE(thesis_rdf_follows_its_equations) {
    // Eq. 3.7-3.10 on FCC: the contact bin holds the origin's 12 neighbours, so
    // g = (12 / N) / (φ · 4π/3 [(R + ΔR/2)³ − (R − ΔR/2)³]) with R the bin centre.
    const Case& fcc = cases()[0];
    const Box fill{Vec3::Constant(-0.6), Vec3::Constant(0.6)};
    const Pack pack = sgmp::testing::lattice_pack(fcc.lattice, kD, fill, Vec3::Constant(0.0123));
    MeasureOptions options;
    const double half = 2.0 * fcc.cell * kD;
    options.region = Box{Vec3::Constant(-half), Vec3::Constant(half)};
    options.gr_bin_width = 0.03;
    options.gr_thesis = true;
    const Measurement m = measure(pack, options);
    BOOST_REQUIRE(m.thesis_rdf.has_value());
    const auto& t = *m.thesis_rdf;
    BOOST_TEST(t.region_count == m.local.rdf.origins);
    const std::size_t bin = bin_of(1.0, 1.0 / 0.03);  // bins centred on k·ΔR
    const double width = 0.03 * kD;
    const double r = static_cast<double>(bin) * width;
    const double shell =
        4.0 * std::numbers::pi / 3.0 * (std::pow(r + width / 2, 3) - std::pow(r - width / 2, 3));
    const double expected = 12.0 / static_cast<double>(t.region_count) / (m.phi * shell);
    BOOST_TEST(std::abs(t.g[bin] - expected) <= 1e-12 * expected);
    BOOST_TEST(t.g[bin - 2] == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
