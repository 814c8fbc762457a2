#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>

#include "sgmp/metrics/measure.hpp"
#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/metrics/parallel.hpp"
#include "synthetic_packs.hpp"

using namespace sgmp;
using namespace sgmp::metrics;

BOOST_AUTO_TEST_SUITE(metrics)

BOOST_AUTO_TEST_CASE(two_spheres_overlapping_by_a_known_depth) {
    Pack pack;
    const double r = 0.05;
    pack.particles.push_back(Particle{7, Vec3(0.0, 0.0, 0.0), r, 0});
    pack.particles.push_back(Particle{3, Vec3(2 * r - 0.01, 0.0, 0.0), r, 0});  // 0.01 deep
    // Through the wall x = 0.625 by 0.02.
    pack.particles.push_back(Particle{5, Vec3(0.625 - r + 0.02, 0.3, 0.0), r, 0});
    const Measurement m = measure(pack, MeasureOptions{});
    BOOST_TEST(m.mean_diameter == 0.1, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(m.overlaps.pairs.count == 1);
    BOOST_TEST(std::abs(m.overlaps.pairs.max_over_d - 0.1) <= 1e-12);
    BOOST_TEST(std::abs(m.overlaps.pairs.mean_over_d - 0.1) <= 1e-12);
    BOOST_TEST(m.overlaps.pairs.worst.at(0).id_a == 3);
    BOOST_TEST(m.overlaps.pairs.worst.at(0).id_b == 7);
    BOOST_TEST(m.overlaps.walls.count == 1);
    BOOST_TEST(std::abs(m.overlaps.walls.max_over_d - 0.2) <= 1e-12);
    BOOST_TEST(m.overlaps.walls.worst.at(0).id_a == 5);
    // Both overlapping spheres are in the control volume: each has one contact at δ = 0.
    BOOST_TEST(m.local.coordination.z_mean[0] == 1.0);
}

BOOST_AUTO_TEST_CASE(polydisperse_contacts_use_each_pairs_radii) {
    Pack pack;
    pack.particles.push_back(Particle{1, Vec3(0.0, 0.0, 0.0), 0.1, 0});
    pack.particles.push_back(Particle{2, Vec3(0.15, 0.0, 0.0), 0.05, 0});  // touching
    pack.particles.push_back(Particle{3, Vec3(0.0, 0.13, 0.0), 0.02, 0});  // 0.01 gap
    const Measurement m = measure(pack, MeasureOptions{});
    BOOST_TEST(m.polydisperse);
    BOOST_TEST(m.mean_diameter == 2.0 * (0.17 / 3.0), boost::test_tools::tolerance(1e-15));
    BOOST_TEST(m.overlaps.pairs.count == 0);
    // Gap 0.01 is 0.088 d: a contact only at δ ≥ 0.1, which is not reported; touching pair
    // counts from 1e-6 on (its gap is rounding-level).
    BOOST_TEST(m.local.coordination.z_mean[1] == 2.0 / 3.0, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(uniform_random_points_give_g_equal_to_one) {
    // 8000 centres uniform in the unit cube (overlaps allowed); every origin's shells are
    // edge-corrected against the cube. Tolerance: 5 standard deviations of the pair count
    // in a bin (each pair is counted from both ends, hence the factor 2).
    const Box cube{Vec3::Constant(-0.5), Vec3::Constant(0.5)};
    const Pack pack = sgmp::testing::uniform_pack(8000, 0.08, cube, 4);
    MeasureOptions options;
    options.region = cube;
    options.gr_bin_width = 0.25;
    options.gr_range = 3.0;
    const Measurement m = measure(pack, options);
    const auto& rdf = m.local.rdf;
    BOOST_TEST(rdf.corrected_origins > 0);
    for (std::size_t k = 0; k < rdf.g.size(); ++k) {
        if (rdf.r_over_d[k] < 1.0) {
            continue;
        }
        const double tolerance = 5.0 * std::sqrt(2.0 / static_cast<double>(rdf.pairs[k]));
        BOOST_TEST(std::abs(rdf.g[k] - 1.0) <= tolerance,
                   "r = " << rdf.r_over_d[k] << " d: g = " << rdf.g[k] << " ± " << tolerance);
    }
}

BOOST_AUTO_TEST_CASE(split_ratio_of_a_hand_built_cluster) {
    // One origin with three neighbours at √3·d and two at 2·d (and one far above, which lifts
    // the top of the space so every window lies inside it): split = (3 / V(√3)) / (2 / V(2))
    // with V(r0) = (r0 + 0.05)³ − (r0 − 0.05)³, whatever the density. 1e-9 relative: volume
    // rounding only.
    const double d = 0.1;
    const double s3 = std::sqrt(3.0) * d;
    const std::vector<Vec3> centers{Vec3(0, 0, 0),       Vec3(s3, 0, 0),    Vec3(-s3, 0, 0),
                                    Vec3(0, 0, s3),      Vec3(0, 2 * d, 0), Vec3(0, -2 * d, 0),
                                    Vec3(0.3, 0.45, 0.3)};
    Pack pack;
    for (std::size_t i = 0; i < centers.size(); ++i) {
        pack.particles.push_back(Particle{static_cast<std::int64_t>(i), centers[i], d / 2, 0});
    }
    MeasureOptions options;
    options.region = Box{Vec3::Constant(-0.01), Vec3::Constant(0.01)};  // the origin alone
    const Measurement m = measure(pack, options);
    const auto volume = [](double r0) { return std::pow(r0 + 0.05, 3) - std::pow(r0 - 0.05, 3); };
    const double expected = (3.0 / volume(std::sqrt(3.0))) / (2.0 / volume(2.0));
    BOOST_TEST(m.local.rdf.split_pairs[0] == 3);
    BOOST_TEST(m.local.rdf.split_pairs[1] == 2);
    BOOST_TEST(std::abs(m.local.rdf.split_ratio - expected) <= 1e-9 * expected,
               m.local.rdf.split_ratio << " vs " << expected);
}

BOOST_AUTO_TEST_CASE(g_of_r_space_choices) {
    // Default: neighbour centres lie in the container shrunk by d/2, up to the highest
    // centre; --gr-container-space: the container up to the top sphere.
    const Pack pack = sgmp::testing::jittered_fcc_pack(1000, 1.05, 0.02, 3);
    MeasureOptions options;
    const Measurement centers = measure(pack, options);
    options.gr_container_space = true;
    const Measurement container = measure(pack, options);
    const double r = 0.5 * centers.mean_diameter;
    const Box& a = centers.local.rdf.space;
    const Box& b = container.local.rdf.space;
    BOOST_TEST(std::abs(a.lo.x() - (-0.625 + r)) <= 1e-15);
    BOOST_TEST(std::abs(a.lo.y() - (-0.625 + r)) <= 1e-15);
    BOOST_TEST(std::abs(a.hi.y() - (centers.top - r)) <= 1e-14);  // (y + r) - r rounding
    BOOST_TEST(b.lo.x() == -0.625);
    BOOST_TEST(b.hi.y() == container.top);
    // Same pairs, larger space and lower density: g rises by about |container| / |centres|.
    BOOST_TEST((centers.local.rdf.pairs == container.local.rdf.pairs));
    BOOST_TEST(container.local.rdf.density < centers.local.rdf.density);
}

BOOST_AUTO_TEST_CASE(results_do_not_depend_on_the_thread_count) {
    const Pack pack = sgmp::testing::jittered_fcc_pack(2000, 1.02, 0.05, 11);
    std::vector<std::string> dumps;
    for (const unsigned threads : {1u, 2u, 3u}) {
        MeasureOptions options;
        options.threads = threads;
        const Measurement m = measure(pack, options);
        dumps.push_back(metrics_json(m, {}).dump());
    }
    BOOST_TEST(dumps[0] == dumps[1]);
    BOOST_TEST(dumps[0] == dumps[2]);
}

BOOST_AUTO_TEST_CASE(phi_profile_matches_phi_over_the_same_box) {
    // Slabs of the control volume's cross-section from -0.5 to 0.5 sum to φ of the box.
    const Pack pack = sgmp::testing::jittered_fcc_pack(3000, 1.03, 0.05, 2);
    MeasureOptions options;
    const Measurement m = measure(pack, options);
    const double d = m.mean_diameter;
    const auto profile =
        packing_fraction_profile(pack.particles, control_volume(), -0.5, 0.5, 0.37 * d);
    double volume = 0.0;
    for (std::size_t k = 0; k < profile.phi.size(); ++k) {
        volume += profile.phi[k] * (profile.y_hi[k] - profile.y_lo[k]);
    }
    BOOST_TEST(std::abs(volume - m.phi) <= 1e-10);
}

BOOST_AUTO_TEST_CASE(a_slab_thicker_than_the_column_is_the_column) {
    // A thickness of 1e15 d once gave zero slabs and an index past the end (SIGSEGV).
    const Pack pack = sgmp::testing::jittered_fcc_pack(500, 1.05, 0.01, 1);
    const Measurement m = measure(pack, MeasureOptions{});
    const auto profile = packing_fraction_profile(pack.particles, control_volume(), -0.5, 0.5,
                                                  1e15 * m.mean_diameter);
    BOOST_TEST_REQUIRE(profile.phi.size() == 1u);
    BOOST_TEST(std::abs(profile.phi[0] - m.phi) <= 1e-10);  // the column is the control volume
    MeasureOptions huge;
    for (const double slab : {1e15, 1e308, std::numeric_limits<double>::infinity(),
                              std::numeric_limits<double>::quiet_NaN()}) {
        huge.slab_thickness = slab;
        BOOST_CHECK_THROW(measure(pack, huge), std::invalid_argument);
    }
}

BOOST_AUTO_TEST_CASE(bad_regions_and_options_are_refused) {
    const Pack pack = sgmp::testing::jittered_fcc_pack(500, 1.05, 0.01, 1);
    MeasureOptions options;
    options.region = Box{Vec3(-0.7, -0.5, -0.5), Vec3(0.5, 0.5, 0.5)};  // through a wall
    BOOST_CHECK_THROW(measure(pack, options), std::invalid_argument);
    options.region = Box{Vec3(0.2, -0.5, -0.5), Vec3(0.1, 0.5, 0.5)};  // inverted
    BOOST_CHECK_THROW(measure(pack, options), std::invalid_argument);
    options.region = Box{Vec3(-0.5, 3.0, -0.5), Vec3(0.5, 4.0, 0.5)};  // above the pack
    BOOST_CHECK_THROW(measure(pack, options), std::invalid_argument);
    options = MeasureOptions{};
    options.gr_bin_width = 0.0;
    BOOST_CHECK_THROW(measure(pack, options), std::invalid_argument);
    options = MeasureOptions{};
    options.gr_bin_width = 6.0;  // wider than the range
    BOOST_CHECK_THROW(measure(pack, options), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
