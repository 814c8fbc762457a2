#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "sgmp/compare/agreement.hpp"
#include "sgmp/compare/report_files.hpp"
#include "sgmp/compare/report_plots.hpp"
#include "synthetic_packs.hpp"

using namespace sgmp;
using namespace sgmp::compare;
namespace fs = std::filesystem;

namespace {

/// Jittered FCC packs of 600 particles, seeds 1..n, nearest neighbours `spacing`·d apart.
Group group(const std::string& label, double spacing, int n, std::size_t count = 600) {
    Group g;
    g.label = label;
    for (int seed = 1; seed <= n; ++seed) {
        const Pack pack = sgmp::testing::jittered_fcc_pack(count, spacing, 0.04, seed);
        const Measurement m = measure(pack, MeasureOptions{});
        g.packs.push_back(summarise(label + std::to_string(seed) + ".xyz", pack, m));
    }
    return g;
}

const MetricRow& row(const Comparison& c, const std::string& name) {
    for (const auto& r : c.rows) {
        if (r.name == name) {
            return r;
        }
    }
    throw std::runtime_error("no row " + name);
}

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(SGMP_BINARY_DIR) / "compare-test-scratch" / name;
    fs::remove_all(dir);
    fs::create_directories(dir.parent_path());
    return dir;
}

std::string read(const fs::path& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(report)

ReportPlan plan_of(std::vector<std::pair<std::size_t, std::size_t>> comparisons) {
    ReportPlan plan;
    plan.comparisons = std::move(comparisons);
    return plan;
}

BOOST_AUTO_TEST_CASE(identical_inputs_agree_everywhere) {
    const Group b = group("B", 1.05, 3);
    Group a = b;
    a.label = "A";
    const Report r = build_report({a, b}, plan_of({{0, 1}}));
    BOOST_REQUIRE(r.comparisons.size() == 1u);
    const Comparison& c = r.comparisons[0];
    BOOST_TEST(c.count == 600u);
    for (const auto& row : c.rows) {
        const Verdict expected = metric_rule(row.name).judged ? Verdict::Agree : Verdict::Info;
        BOOST_TEST(row.verdict == expected, row.name);
        BOOST_TEST(row.difference == 0.0);
        BOOST_TEST(row.ratio.has_value(), row.name);
    }
    BOOST_TEST(c.row("g_r").tolerance > 0.0);  // the replicates differ
    BOOST_TEST(c.count_of(Verdict::Differ) == 0u);
}

BOOST_AUTO_TEST_CASE(a_shifted_input_differs) {
    // Spacing 1.05 d against 1.12 d: the lattice is looser (600 particles do not fill the
    // control volume, so φ there drops by less than (1.05/1.12)³) and the g(r) peaks move.
    const Report r = build_report({group("A", 1.12, 2), group("B", 1.05, 3)}, plan_of({{0, 1}}));
    const Comparison& c = r.comparisons.at(0);
    BOOST_TEST(row(c, "phi").verdict == Verdict::Differ);
    BOOST_TEST(row(c, "phi").difference < -0.01);
    BOOST_TEST(*row(c, "g_r").ratio > 1.0);
    BOOST_TEST(row(c, "g_r").verdict == Verdict::Differ);
    BOOST_TEST(c.count_of(Verdict::Differ) >= 2u);
}

BOOST_AUTO_TEST_CASE(several_groups_and_unmatched_counts) {
    // One candidate against two references; a count present on one side only is noted.
    std::vector<Group> groups{group("SGMP", 1.05, 2), group("DEM-mu0", 1.05, 2),
                              group("DEM-mu05", 1.12, 2)};
    const Group extra = group("SGMP", 1.05, 1, 300);
    groups[0].packs.push_back(extra.packs[0]);
    const Report r = build_report(groups, plan_of({{0, 1}, {0, 2}}));
    BOOST_TEST(r.comparisons.size() == 2u);
    BOOST_TEST(r.comparisons[0].reference == "DEM-mu0");
    BOOST_TEST(r.comparisons[1].reference == "DEM-mu05");
    BOOST_TEST(r.comparisons[0].count_of(Verdict::Differ) == 0u);
    BOOST_TEST(r.comparisons[1].count_of(Verdict::Differ) > 0u);
    BOOST_TEST(r.notes.size() == 2u);  // 300 particles: only in SGMP, noted per comparison
    BOOST_CHECK_THROW(build_report(groups, plan_of({{0, 3}})), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(classes_that_cannot_be_told_apart_make_verdicts_inconclusive) {
    // Two classes made of the same packs cannot be told apart by any metric, so agreeing
    // with either is no evidence: every judged verdict against them is inconclusive. A third
    // class that differs (spacing 1.12) keeps its power where both others differ from it.
    std::vector<Group> groups{group("SGMP", 1.05, 2), group("C1", 1.05, 3), group("C2", 1.05, 3),
                              group("C3", 1.12, 3)};
    ReportPlan plan = plan_of({{0, 1}, {0, 3}});
    plan.class_sets = {{1, 2, 3}};
    const Report r = build_report(groups, plan);
    for (const auto& row : r.comparisons[0].rows) {
        const Verdict expected =
            metric_rule(row.name).judged ? Verdict::Inconclusive : Verdict::Info;
        BOOST_TEST(row.verdict == expected,
                   row.name << ": " << row.candidate_mean << " vs " << row.reference_mean);
        BOOST_TEST(!row.power, row.name);
    }
    const Comparison& against_c3 = r.comparisons[1];
    BOOST_TEST(against_c3.row("phi").power);
    BOOST_TEST(against_c3.row("phi").verdict == Verdict::Differ);
}

BOOST_AUTO_TEST_CASE(the_model_spread_widens_the_tolerance) {
    // Reference B and its variant V (spacing 1.06 instead of 1.05): their φ offset enters
    // the tolerance (as 2·M) in quadrature with 2 sd, so a candidate at V's φ agrees.
    const Group b = group("B", 1.05, 3);
    const Group v = group("V", 1.06, 3);
    Group a = v;
    a.label = "A";
    ReportPlan plan = plan_of({{0, 1}});
    const Report without = build_report({a, b, v}, plan);
    plan.variants[1] = 2;
    const Report with = build_report({a, b, v}, plan);
    const MetricRow& plain = without.comparisons[0].row("phi");
    const MetricRow& wide = with.comparisons[0].row("phi");
    BOOST_TEST(plain.model_spread == 0.0);
    // One variant count: M = |offset|, entering at 2·M beside 2 sd.
    BOOST_TEST(wide.model_spread == 2.0 * std::abs(plain.difference),
               boost::test_tools::tolerance(1e-12));
    BOOST_TEST(
        wide.tolerance == std::max(0.005, std::hypot(plain.seed_spread, 2.0 * plain.difference)),
        boost::test_tools::tolerance(1e-12));
    BOOST_TEST(wide.verdict == Verdict::Agree);
    BOOST_TEST(with.comparisons[0].variant_packs == 3u);
}

BOOST_AUTO_TEST_CASE(report_directory_with_and_without_gnuplot) {
    const Report r = build_report({group("A", 1.05, 1), group("B", 1.05, 2)}, plan_of({{0, 1}}));
    ReportContext context;
    context.command = "test";
    // Without gnuplot: the tables come out and say the plots were skipped.
    ::setenv("SGMP_GNUPLOT", "", 1);
    const fs::path plain = scratch("no-plots");
    const auto used = write_report(plain, false, r, context);
    BOOST_TEST(!used.plots_made);
    for (const char* file : {"report.md", "report.csv", "report.json", "index.html"}) {
        BOOST_TEST(fs::exists(plain / file), file);
    }
    BOOST_TEST(read(plain / "report.md").find("Plots were skipped") != std::string::npos);
    // An existing directory is kept without overwrite.
    BOOST_CHECK_THROW(write_report(plain, false, r, context), std::exception);
    ::unsetenv("SGMP_GNUPLOT");
    const auto gnuplot = find_gnuplot();
    if (gnuplot) {
        const fs::path full = scratch("plots");
        const auto made = write_report(full, false, r, context);
        BOOST_TEST(made.plots_made, made.plots_note);
        BOOST_TEST(made.plot_files.size() == 4u);
        for (const auto& file : made.plot_files) {
            BOOST_TEST(read(full / file).find("<svg") != std::string::npos, file);
        }
        BOOST_TEST(read(full / "index.html").find("<svg") != std::string::npos);
    } else {
        BOOST_TEST_MESSAGE("gnuplot not installed: plot output not checked");
    }
}

BOOST_AUTO_TEST_SUITE_END()
