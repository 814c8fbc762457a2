// summary.csv: layout, quoting, parsing and the merge of shard summaries.
#include <boost/test/unit_test.hpp>
#include <stdexcept>

#include "sgmp/batch/plan.hpp"
#include "sgmp/batch/summary.hpp"
#include "sgmp/pack/csv_fields.hpp"
#include "sgmp/pack/input_error.hpp"

using namespace sgmp::batch;

namespace {

SummaryRow row_for(std::size_t job, const std::string& path) {
    SummaryRow row;
    row.job = job;
    for (const Parameter& p : parameters()) {
        row.values.push_back(p.default_value);
    }
    row.values[parameter_index("size_modes")] = "1:0.7,0.5:0.3";  // holds commas
    row.seed = 10 + job;
    row.seconds = 0.25;
    PackMetrics m;
    m.phi = 0.1 + 0.2;  // 0.30000000000000004: written so it reads back exactly
    m.z_mean = {1, 2, 3, 4, 5, 6};
    m.split_ratio = 0.75;
    row.metrics = m;
    row.path = path;
    return row;
}

}  // namespace

BOOST_AUTO_TEST_CASE(rows_round_trip_through_the_csv_layout) {
    const std::string line = summary_line(row_for(4, "a \"b\",c.xyz"));
    const auto fields = sgmp::split_quoted_csv_line(line.substr(0, line.size() - 1));
    BOOST_REQUIRE(fields);
    BOOST_TEST(fields->size() == summary_header().size());
    BOOST_TEST(fields->front() == "4");
    BOOST_TEST(fields->back() == "a \"b\",c.xyz");
    BOOST_TEST((*fields)[1 + parameter_index("size_modes")] == "1:0.7,0.5:0.3");
    const auto header = summary_header();
    const auto at = [&](const std::string& name) {
        return (*fields)[std::find(header.begin(), header.end(), name) - header.begin()];
    };
    BOOST_TEST(std::stod(at("phi")) == 0.1 + 0.2);
    BOOST_TEST(at("z_5e-2") == "6");
    BOOST_TEST(at("voronoi_phi_mean") == "");
    BOOST_TEST(at("measure_seconds") == "");
    SummaryRow unmeasured = row_for(1, "p");
    unmeasured.metrics.reset();
    const std::string bare = summary_line(unmeasured);
    BOOST_TEST(sgmp::split_quoted_csv_line(bare.substr(0, bare.size() - 1))->size() ==
               header.size());
}

BOOST_AUTO_TEST_CASE(merge_restores_job_order_and_refuses_duplicates) {
    const std::string a =
        summary_text({summary_line(row_for(2, "c")), summary_line(row_for(0, "a"))});
    const std::string b = summary_text({summary_line(row_for(1, "b"))});
    const std::string merged = merge_summaries({parse_summary(a, "a"), parse_summary(b, "b")});
    const std::string serial =
        summary_text({summary_line(row_for(0, "a")), summary_line(row_for(1, "b")),
                      summary_line(row_for(2, "c"))});
    BOOST_TEST(merged == serial);
    BOOST_CHECK_THROW(merge_summaries({parse_summary(a, "a"), parse_summary(a, "a")}),
                      std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(parse_refuses_foreign_tables) {
    BOOST_CHECK_THROW(parse_summary("a,b\n1,2\n", "x"), sgmp::InputError);
    BOOST_CHECK_THROW(parse_summary("", "x"), sgmp::InputError);
    const std::string text = summary_text({"7,1\n"});
    BOOST_CHECK_THROW(parse_summary(text, "x"), sgmp::InputError);
}
