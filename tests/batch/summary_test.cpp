// summary.csv: layout, quoting, parsing and the merge of shard summaries.
#include <boost/test/unit_test.hpp>
#include <stdexcept>

#include "sgmp/batch/plan.hpp"
#include "sgmp/batch/summary.hpp"
#include "sgmp/metrics/summary_columns.hpp"
#include "sgmp/pack/csv_fields.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/metadata.hpp"

using namespace sgmp::batch;

namespace {

/// The schema `sgmp batch` writes: sgmp-compare's metric columns.
const SummarySchema& schema() {
    static const SummarySchema s(sgmp::metrics::summary_column_names());
    return s;
}

SummaryRow row_for(std::size_t job, const std::string& path) {
    SummaryRow row;
    row.job = job;
    for (const Parameter& p : parameters()) {
        row.values.push_back(p.default_value);
    }
    row.values[parameter_index("size_modes")] = "1:0.7,0.5:0.3";  // holds commas
    row.seed = 10 + job;
    row.seconds = 0.25;
    for (const auto& column : sgmp::metrics::summary_columns()) {
        row.metric_fields.push_back(column.optional ? "" : "1");
    }
    // 0.30000000000000004: written so it reads back exactly.
    row.metric_fields.front() = sgmp::format_number(0.1 + 0.2);
    row.path = path;
    return row;
}

}  // namespace

BOOST_AUTO_TEST_CASE(rows_round_trip_through_the_csv_layout) {
    const std::string line = schema().line(row_for(4, "a \"b\",c.xyz"));
    const auto fields = sgmp::split_quoted_csv_line(line.substr(0, line.size() - 1));
    BOOST_REQUIRE(fields);
    BOOST_TEST(fields->size() == schema().header().size());
    BOOST_TEST(fields->front() == "4");
    BOOST_TEST(fields->back() == "a \"b\",c.xyz");
    BOOST_TEST((*fields)[1 + parameter_index("size_modes")] == "1:0.7,0.5:0.3");
    const auto header = schema().header();
    const auto at = [&](const std::string& name) {
        return (*fields)[std::find(header.begin(), header.end(), name) - header.begin()];
    };
    BOOST_TEST(std::stod(at("phi")) == 0.1 + 0.2);
    BOOST_TEST(at("z_5e-2") == "1");
    BOOST_TEST(at("voronoi_phi_mean") == "");
    BOOST_TEST(at("measure_seconds") == "");
    SummaryRow unmeasured = row_for(1, "p");
    unmeasured.metric_fields.clear();
    const std::string bare = schema().line(unmeasured);
    BOOST_TEST(sgmp::split_quoted_csv_line(bare.substr(0, bare.size() - 1))->size() ==
               header.size());
}

BOOST_AUTO_TEST_CASE(merge_restores_job_order_and_refuses_duplicates) {
    const std::string a =
        schema().text({schema().line(row_for(2, "c")), schema().line(row_for(0, "a"))});
    const std::string b = schema().text({schema().line(row_for(1, "b"))});
    const std::string merged = schema().merge({schema().parse(a, "a"), schema().parse(b, "b")});
    const std::string serial =
        schema().text({schema().line(row_for(0, "a")), schema().line(row_for(1, "b")),
                       schema().line(row_for(2, "c"))});
    BOOST_TEST(merged == serial);
    BOOST_CHECK_THROW(schema().merge({schema().parse(a, "a"), schema().parse(a, "a")}),
                      std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(parse_refuses_foreign_tables) {
    BOOST_CHECK_THROW(schema().parse("a,b\n1,2\n", "x"), sgmp::InputError);
    BOOST_CHECK_THROW(schema().parse("", "x"), sgmp::InputError);
    const std::string text = schema().text({"7,1\n"});
    BOOST_CHECK_THROW(schema().parse(text, "x"), sgmp::InputError);
}

BOOST_AUTO_TEST_CASE(a_measured_row_has_one_field_per_metric_column) {
    SummaryRow row = row_for(3, "p");
    row.metric_fields.pop_back();
    BOOST_CHECK_THROW(schema().line(row), std::invalid_argument);
    // The batch's own columns come first, the metric columns in the table's order, then path.
    const auto header = schema().header();
    const auto metrics = sgmp::metrics::summary_column_names();
    BOOST_TEST(header.back() == "path");
    BOOST_TEST(std::equal(metrics.begin(), metrics.end(), header.end() - 1 - metrics.size()));
}
