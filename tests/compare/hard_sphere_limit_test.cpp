// The hard-sphere limit of a DEM class (hard_sphere_limit.hpp) and its place in the report:
// - the coefficient in closed form;
// - metrics that move exactly linearly in E^(-1/3) extrapolate to their E -> infinity value;
// - pours pair by count and seed, and a stiff pour without its pour is named;
// - the limit is a reference of its own, judged for power against the other classes'
//   limits only, with the stiff pours as its model spread.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <sstream>

#include "sgmp/compare/crossval.hpp"
#include "sgmp/compare/hard_sphere_limit.hpp"
#include "sgmp/compare/measure.hpp"
#include "synthetic_packs.hpp"

using namespace sgmp;
using namespace sgmp::compare;

namespace {

/// A pack summary of a pour at Young's modulus `youngs` whose every metric is
/// X(E) = base + slope·E^(−1/3) (E^(−1/3) in units of (10⁹ Pa)^(−1/3)).
PackSummary pour_at(double youngs, std::size_t count, int seed, double base, double slope) {
    const double x = std::cbrt(1e9 / youngs);
    PackSummary p;
    p.source = "n" + std::to_string(count) + "-E" + std::to_string(youngs) + "-seed" +
               std::to_string(seed);
    p.provenance = {{"seed", std::to_string(seed)}, {kYoungsModulusKey, std::to_string(youngs)}};
    p.count = count;
    p.diameter = 0.1;
    for (const auto& rule : metric_rules()) {
        if (rule.kind == MetricKind::Scalar) {
            p.scalars.push_back(base + slope * x);
        }
    }
    p.gr_bin_width = 0.02;
    p.gr_r = {1.11, 1.13, 1.15};
    p.gr = {base + slope * x, 2 * base - slope * x, base};
    for (std::size_t t = 0; t < coordination_tolerance_names().size(); ++t) {
        p.z_mean.push_back(5.0 + static_cast<double>(t) + slope * x);
        p.p_z.push_back({0.5 - 0.1 * slope * x, 0.5 + 0.1 * slope * x});
    }
    p.p_z[1] = {0.25, 0.75 - slope * x};
    p.phi_y_mid = {0.0};
    p.phi_y = {0.6 + x};
    return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(hard_sphere_limit_of_a_class)

BOOST_AUTO_TEST_CASE(the_coefficient_is_the_closed_form) {
    // 1 / (16^(1/3) − 1) = 0.657970...; exact to rounding.
    BOOST_TEST(hard_sphere_coefficient(1e9, 1.6e10) == 1.0 / (std::cbrt(16.0) - 1.0),
               boost::test_tools::tolerance(1e-15));
    BOOST_TEST(std::abs(hard_sphere_coefficient(1e9, 1.6e10) - 0.65797) < 1e-5);
    BOOST_TEST(hard_sphere_coefficient(5e8, 4e9) == 1.0);  // 8^(1/3) − 1 = 1
    BOOST_CHECK_THROW(hard_sphere_coefficient(1e9, 1e9), std::invalid_argument);
    BOOST_CHECK_THROW(hard_sphere_coefficient(0.0, 1e9), std::invalid_argument);
    BOOST_CHECK_THROW(hard_sphere_coefficient(2e9, 1e9), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(metrics_linear_in_the_inverse_cube_root_of_e_extrapolate_exactly) {
    // X = 6 + 0.3·E^(−1/3): the limit is 6 for every scalar but the overlaps (0) and for every
    // g(r) bin; Z and P(Z) reach their constant parts. Tolerance 1e-12: a few roundings of
    // numbers of order 10.
    const PackSummary soft = pour_at(1e9, 3000, 1, 6.0, 0.3);
    const PackSummary stiff = pour_at(1.6e10, 3000, 1, 6.0, 0.3);
    const PackSummary hard = hard_sphere_limit(soft, stiff);
    std::size_t k = 0;
    for (const auto& rule : metric_rules()) {
        if (rule.kind != MetricKind::Scalar) {
            continue;
        }
        const bool overlap = rule.name.find("overlap") != std::string::npos;
        BOOST_TEST(std::abs(hard.scalars[k] - (overlap ? 0.0 : 6.0)) < 1e-12, rule.name);
        ++k;
    }
    BOOST_TEST(std::abs(hard.gr[0] - 6.0) < 1e-12);
    BOOST_TEST(std::abs(hard.gr[1] - 12.0) < 1e-12);
    BOOST_TEST(std::abs(hard.gr[2] - 6.0) < 1e-12);
    BOOST_TEST(std::abs(hard.z_mean[0] - 5.0) < 1e-12);
    BOOST_TEST(std::abs(hard.p_z[0][0] - 0.5) < 1e-12);
    BOOST_TEST(std::abs(hard.p_z[1][1] - 0.75) < 1e-12);
    BOOST_TEST(hard.phi_y == stiff.phi_y);  // not judged: the stiff pour's profile
    BOOST_TEST(hard.gr_r == stiff.gr_r);
    BOOST_TEST(hard.count == 3000u);
    // A pour without a modulus, or not stiffer, has no limit.
    PackSummary bare = soft;
    bare.provenance = {{"seed", "1"}};
    BOOST_CHECK_THROW(hard_sphere_limit(bare, stiff), std::invalid_argument);
    BOOST_CHECK_THROW(hard_sphere_limit(stiff, soft), std::invalid_argument);
    PackSummary garbled = stiff;
    garbled.provenance = {{"seed", "1"}, {kYoungsModulusKey, "1.6e10Pa"}};
    BOOST_CHECK_THROW(hard_sphere_limit(soft, garbled), std::invalid_argument);
    BOOST_CHECK_THROW(hard_sphere_limit(soft, pour_at(1.6e10, 9000, 1, 6.0, 0.3)),
                      std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(a_limit_is_labelled_after_its_class) {
    BOOST_TEST(hard_sphere_limit_label("DEM mu=0") == "DEM mu=0 hard-sphere limit");
    BOOST_TEST(*class_of_hard_sphere_limit("DEM mu=0 hard-sphere limit") == "DEM mu=0");
    BOOST_TEST(!class_of_hard_sphere_limit("DEM mu=0").has_value());
}

BOOST_AUTO_TEST_CASE(pours_pair_by_count_and_seed) {
    const Group soft{"DEM mu=0",
                     {pour_at(1e9, 3000, 1, 6.0, 0.3), pour_at(1e9, 3000, 2, 6.1, 0.3),
                      pour_at(1e9, 9000, 1, 6.2, 0.3)}};
    const Group stiff{"DEM mu=0 (stiff)",
                      {pour_at(1.6e10, 3000, 2, 6.1, 0.3), pour_at(1.6e10, 3000, 1, 6.0, 0.3),
                       pour_at(1.6e10, 3000, 4, 6.0, 0.3)}};
    std::vector<std::string> unpaired;
    const Group limit = hard_sphere_limit(soft, stiff, "L", unpaired);
    BOOST_TEST(limit.label == "L");
    BOOST_REQUIRE(limit.packs.size() == 2u);  // seed 4 has no pour; 9000 was not settled
    BOOST_TEST(std::abs(limit.packs[0].scalars[0] - 6.1) < 1e-12);  // seed 2 with seed 2
    BOOST_TEST(std::abs(limit.packs[1].scalars[0] - 6.0) < 1e-12);
    BOOST_REQUIRE(unpaired.size() == 1u);
    BOOST_TEST(unpaired[0].find("seed4") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_limit_is_a_reference_of_its_own_with_its_own_class_set) {
    std::istringstream manifest(
        "role,group,count,seed,seconds,path\n"
        "candidate,relaxed,600,1,0.5,c1\n"
        "reference,smooth,600,1,100,s1\n"
        "reference,rough,600,1,50,r1\n"
        "variant,rough,600,1,,rv1\n"
        "stiff,smooth,600,1,,ss1\n"
        "stiff,rough,600,1,,rs1\n");
    GroupPlan plan = plan_groups(read_manifest(manifest, "m"));
    BOOST_REQUIRE(plan.stiff.size() == 2u);
    BOOST_TEST(plan.labels[4] == "smooth (stiff)");
    // The stiff pours are the model spread of a class without a variant set only.
    BOOST_TEST(plan.plan.variants.at(1) == 4u);
    BOOST_TEST(plan.plan.variants.at(2) == 3u);

    std::vector<Group> groups;
    const double soft_e = 1e9;
    const double stiff_e = 1.6e10;
    groups.push_back({"relaxed", {pour_at(stiff_e, 600, 1, 6.0, 0.0)}});
    groups.push_back({"smooth", {pour_at(soft_e, 600, 1, 6.0, 0.3)}});
    groups.push_back({"rough", {pour_at(soft_e, 600, 1, 5.0, 0.3)}});
    groups.push_back({"rough (variant)", {pour_at(soft_e, 600, 1, 5.1, 0.3)}});
    groups.push_back({"smooth (stiff)", {pour_at(stiff_e, 600, 1, 6.0, 0.3)}});
    groups.push_back({"rough (stiff)", {pour_at(stiff_e, 600, 1, 5.0, 0.3)}});
    const auto notes = add_hard_sphere_limits(groups, plan);
    BOOST_TEST(notes.empty());
    BOOST_REQUIRE(groups.size() == 8u);
    BOOST_TEST(groups[6].label == "smooth hard-sphere limit");
    BOOST_TEST(groups[7].label == "rough hard-sphere limit");
    BOOST_TEST(plan.plan.variants.at(6) == 4u);  // a limit's model spread: its stiff pours
    BOOST_TEST(plan.plan.derived_from.at(7) == 2u);
    BOOST_REQUIRE(plan.plan.class_sets.size() == 2u);
    BOOST_TEST((plan.plan.class_sets[1] == std::vector<std::size_t>{6, 7}));
    BOOST_TEST(plan.plan.comparisons.size() == 4u);  // relaxed against 2 classes, 2 limits

    // The runtime beside a limit is its pours'.
    const Report report = build_report(groups, plan.plan);
    std::istringstream again(
        "role,group,count,seed,seconds,path\n"
        "candidate,relaxed,600,1,0.5,c1\n"
        "reference,smooth,600,1,100,s1\n"
        "reference,rough,600,1,50,r1\n");
    const CrossValidation cv = cross_validate(report, read_manifest(again, "m"), {});
    BOOST_REQUIRE(cv.references.size() == 4u);
    BOOST_TEST(cv.references[2] == "smooth hard-sphere limit");
    BOOST_REQUIRE(cv.rows.size() == 1u);
    BOOST_TEST(*cv.rows[0].against[2].speedup == 200.0);
}

BOOST_AUTO_TEST_SUITE_END()
