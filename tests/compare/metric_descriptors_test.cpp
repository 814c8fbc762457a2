// The metric table (metric_descriptors.hpp) against what reads it: metrics.json, the
// summary.csv columns, the report's rules and the names the report's views single out.
#include <boost/test/unit_test.hpp>
#include <set>
#include <string>

#include "sgmp/metrics/coordination_tolerances.hpp"
#include "sgmp/metrics/measure.hpp"
#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/metrics/summary_columns.hpp"
#include "sgmp/report/agreement.hpp"
#include "sgmp/report/crossval.hpp"
#include "synthetic_packs.hpp"

using namespace sgmp;
using namespace sgmp::metrics;

BOOST_AUTO_TEST_SUITE(metric_table)

BOOST_AUTO_TEST_CASE(every_metric_is_declared_once_with_a_definition) {
    std::set<std::string> names;
    for (const MetricDescriptor& d : metric_descriptors()) {
        BOOST_TEST(names.insert(d.name).second, d.name << " twice");
        BOOST_TEST(d.definition.rfind("compare/docs/definitions.md#", 0) == 0, d.name);
        BOOST_TEST(!d.label.empty(), d.name);
        BOOST_TEST(!d.unit.empty(), d.name);
        // A scalar has a value; a curve or distribution is read from the pack's curves.
        BOOST_TEST((d.kind == MetricKind::Scalar) == (d.value != nullptr), d.name);
        BOOST_CHECK(&metric_descriptor(d.name) == &d);
    }
    BOOST_TEST(find_metric("no such metric") == nullptr);
    BOOST_CHECK_THROW(metric_descriptor("no such metric"), std::logic_error);
}

BOOST_AUTO_TEST_CASE(the_families_follow_the_tolerance_list) {
    const auto& names = coordination_tolerance_names();
    for (std::size_t t = 0; t < names.size(); ++t) {
        const MetricDescriptor& z = coordination_metric(t);
        BOOST_TEST(z.name == "z_mean_tol_" + names[t]);
        BOOST_TEST(z.summary_column == "z_" + names[t]);
        BOOST_TEST(z.tolerance == t);
        BOOST_TEST(z.judged == (t != 0));  // Z(δ = 0): information only
        BOOST_TEST(find_metric("wall_contacts_tol_" + names[t]) != nullptr);
    }
    BOOST_CHECK(metric_descriptor("p_z_tol_1e-3").kind == MetricKind::Distribution);
    BOOST_CHECK(metric_descriptor("g_r").kind == MetricKind::Curve);
}

BOOST_AUTO_TEST_CASE(the_report_rules_are_the_table_rows_in_report_order) {
    std::vector<std::string> expected;
    for (const MetricDescriptor& d : metric_descriptors()) {
        if (d.report) {
            expected.push_back(d.name);
        }
    }
    std::vector<std::string> rules;
    for (const report::MetricRule& r : report::metric_rules()) {
        rules.push_back(r.name);
        BOOST_CHECK(r.descriptor != nullptr);
        BOOST_TEST(r.margin == r.descriptor->margin);
    }
    BOOST_TEST(rules == expected, boost::test_tools::per_element());
    // The order the report has always had: scalars, curves, then information.
    BOOST_TEST(rules.front() == "phi");
    BOOST_TEST(rules.back() == "wall_overlaps");
    const std::vector<std::string> headline{"phi",         "z_mean_tol_1e-3", "z_mean_tol_1e-2",
                                            "split_ratio", "p_z_tol_1e-3",    "g_r"};
    BOOST_TEST(report::headline_metrics() == headline, boost::test_tools::per_element());
    const std::vector<std::string> trends{"phi", "z_mean_tol_1e-3", "split_ratio"};
    BOOST_TEST(ranked_metric_names(&MetricDescriptor::trend_rank) == trends,
               boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(the_summary_columns_are_the_table_columns) {
    const std::vector<std::string> expected{
        "phi",           "z_0",         "z_1e-6",          "z_1e-3",      "z_1e-2",
        "z_2e-2",        "z_5e-2",      "overlaps",        "overlap_max", "overlap_mean",
        "wall_overlaps", "split_ratio", "voronoi_phi_mean"};
    BOOST_TEST(summary_column_names() == expected, boost::test_tools::per_element());
    for (const SummaryColumn& c : summary_columns()) {
        BOOST_TEST(metric_descriptor(c.metric).summary_column == c.column);
        BOOST_CHECK(summary_column_of(c.metric) == &c);
    }
}

BOOST_AUTO_TEST_CASE(metrics_json_holds_every_metric_of_the_table_with_its_value) {
    const Pack pack =
        testing::uniform_pack(200, 0.1, Box{Vec3(-0.5, -0.6, -0.5), Vec3(0.5, 0.4, 0.5)}, 3);
    const Measurement m = measure(pack, MeasureOptions{});
    const auto j = metrics_json(m, nlohmann::ordered_json::object());
    std::size_t written = 0;
    for (const MetricDescriptor& d : metric_descriptors()) {
        if (d.json_rank == kUnranked) {
            BOOST_TEST(!j.contains(d.name), d.name);
            continue;
        }
        const auto value = d.value(m, d.tolerance);
        BOOST_TEST_REQUIRE(value.has_value(), d.name);
        BOOST_TEST_REQUIRE(j.contains(d.name), d.name);
        BOOST_TEST(j.at(d.name).get<double>() == *value, d.name);
        BOOST_TEST(j.at(d.name).is_number_integer() == d.integer, d.name);
        ++written;
    }
    BOOST_TEST(written > 20U);
    // The keys come in json_rank order: the head before "region", the detail after it.
    std::vector<std::string> keys;
    for (const auto& [key, value] : j.items()) {
        if (find_metric(key) != nullptr) {
            keys.push_back(key);
        }
    }
    BOOST_TEST(keys == ranked_metric_names(&MetricDescriptor::json_rank),
               boost::test_tools::per_element());
}

BOOST_AUTO_TEST_SUITE_END()
