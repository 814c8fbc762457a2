#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "sgmp/report/agreement.hpp"
#include "sgmp/report/dem_parameters.hpp"
#include "sgmp/report/report_files.hpp"
#include "sgmp/report/report_plots.hpp"
#include "synthetic_packs.hpp"

using namespace sgmp;
using namespace sgmp::metrics;
using namespace sgmp::report;
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
        // Δ = 0: agree wherever the interval's half-width is below the margin (power), else
        // inconclusive; never differ.
        const Verdict expected = !metric_rule(row.name).judged
                                     ? Verdict::Info
                                     : (row.power ? Verdict::Agree : Verdict::Inconclusive);
        BOOST_TEST(row.verdict == expected, row.name);
        BOOST_TEST(row.difference == 0.0);
        BOOST_TEST(row.ratio.has_value(), row.name);
    }
    BOOST_TEST(c.row("g_r").seed_spread > 0.0);  // the replicates differ
    BOOST_TEST(c.count_of(Verdict::Differ) == 0u);
    BOOST_TEST(c.row("phi").verdict == Verdict::Agree);
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

BOOST_AUTO_TEST_CASE(classes_are_judged_against_each_other_and_change_no_verdict) {
    // Two classes made of the same packs and a third that differs (spacing 1.12): the class
    // set adds class-against-class comparisons, and every verdict against a class is what it
    // is without the set (no power rule rewrites a difference or an agreement).
    std::vector<Group> groups{group("SGMP", 1.05, 2), group("C1", 1.05, 3), group("C2", 1.05, 3),
                              group("C3", 1.12, 3)};
    ReportPlan plan = plan_of({{0, 1}, {0, 3}});
    const Report plain = build_report(groups, plan);
    plan.class_sets = {{1, 2, 3}};
    const Report with = build_report(groups, plan);
    BOOST_TEST(plain.class_comparisons.empty());
    BOOST_TEST_REQUIRE(with.class_comparisons.size() == 3u);  // C1–C2, C1–C3, C2–C3 at 600
    BOOST_TEST(with.class_comparisons[0].candidate == "C1");
    BOOST_TEST(with.class_comparisons[0].reference == "C2");
    BOOST_TEST(with.class_comparisons[0].count_of(Verdict::Differ) == 0u);
    BOOST_TEST(with.class_comparisons[1].row("phi").verdict == Verdict::Differ);
    for (std::size_t c = 0; c < 2; ++c) {
        for (std::size_t m = 0; m < plain.comparisons[c].rows.size(); ++m) {
            BOOST_TEST(plain.comparisons[c].rows[m].verdict == with.comparisons[c].rows[m].verdict,
                       plain.comparisons[c].rows[m].name);
        }
    }
    BOOST_TEST(with.comparisons[1].row("phi").verdict == Verdict::Differ);
}

BOOST_AUTO_TEST_CASE(every_row_carries_its_interval_margin_and_mdd) {
    const Report r = build_report({group("A", 1.05, 2), group("B", 1.05, 3)}, plan_of({{0, 1}}));
    for (const auto& row : r.comparisons.at(0).rows) {
        if (row.verdict == Verdict::Info) {
            continue;
        }
        BOOST_TEST(row.margin == metric_rule(row.name).margin, row.name);
        BOOST_TEST(row.tolerance == row.margin, row.name);
        BOOST_TEST(row.model_spread == 0.0, row.name);
        BOOST_TEST(row.ci_low <= row.ci_high, row.name);
        BOOST_TEST(row.mdd > row.margin, row.name);
        // The interval holds the estimate (curves: the interval of the true distance; the
        // observed L2 distance of g(r) overstates it by the noise, D̂² = ‖Δ‖² + ‖ε‖² on average,
        // so there it may lie above the upper bound).
        BOOST_TEST(row.ci_low <= row.difference, row.name);
        BOOST_TEST((row.name == "g_r" || row.difference <= row.ci_high), row.name);
        const bool inside = row.ci_low >= -row.margin && row.ci_high <= row.margin;
        BOOST_TEST((row.verdict == Verdict::Agree) == inside, row.name);
    }
}

BOOST_AUTO_TEST_CASE(a_relaxed_pack_without_a_true_certificate_is_not_judged) {
    Group relaxed = group("R", 1.05, 2);
    relaxed.packs[0].provenance.emplace_back("relax", "frictionless");
    relaxed.packs[0].provenance.emplace_back("certified", "false");
    relaxed.packs[0].provenance.emplace_back("certificate_residual_max", "1.45");
    const Report r = build_report({relaxed, group("B", 1.05, 3)}, plan_of({{0, 1}}));
    const Comparison& c = r.comparisons.at(0);
    BOOST_TEST(c.invalid == "1 pack not certified (largest residual 1.45 m·g)");
    BOOST_TEST(c.count_of(Verdict::Info) == c.rows.size());
    BOOST_TEST(c.row("phi").tolerance_rule.rfind("not certified (would be ", 0) == 0u);
    // Certified, or claiming no equilibrium (no relax key): judged.
    relaxed.packs[0].provenance.pop_back();                      // the residual
    relaxed.packs[0].provenance.back() = {"certified", "true"};  // was false
    const Report ok = build_report({relaxed, group("B", 1.05, 3)}, plan_of({{0, 1}}));
    BOOST_TEST(ok.comparisons.at(0).invalid.empty());
    BOOST_TEST(ok.comparisons.at(0).row("phi").verdict == Verdict::Agree);
    BOOST_TEST(uncertified_reason(group("T", 1.05, 1).packs[0]).empty());
}

BOOST_AUTO_TEST_CASE(physically_impossible_values_are_refused) {
    const Group g = group("A", 1.05, 1);
    BOOST_CHECK_NO_THROW(check_physical(g.packs[0]));
    const auto scalar_index = [](const std::string& name) {
        std::size_t k = 0;
        for (const auto& rule : metric_rules()) {
            if (rule.name == name) {
                return k;
            }
            k += rule.kind == MetricKind::Scalar ? 1 : 0;
        }
        return k;
    };
    PackSummary p = g.packs[0];
    p.scalars[scalar_index("phi")] = 0.75;  // above Kepler's bound for one size
    BOOST_CHECK_THROW(check_physical(p), std::invalid_argument);
    p = g.packs[0];
    p.scalars[scalar_index("z_mean_tol_1e-3")] = -0.1;
    BOOST_CHECK_THROW(check_physical(p), std::invalid_argument);
    p = g.packs[0];
    p.scalars[scalar_index("overlaps")] = -5.0;
    BOOST_CHECK_THROW(check_physical(p), std::invalid_argument);
    p = g.packs[0];
    // NaN in a summary means "not measured" (a batch row's empty field: precomputed.hpp's
    // readers refuse a measured NaN); it is not judged.
    p.scalars[scalar_index("phi")] = std::nan("");
    BOOST_CHECK_NO_THROW(check_physical(p));
    p.scalars[scalar_index("phi")] = INFINITY;
    BOOST_CHECK_THROW(check_physical(p), std::invalid_argument);
    p = g.packs[0];
    p.gr[10] = -0.01;
    BOOST_CHECK_THROW(check_physical(p), std::invalid_argument);
    p = g.packs[0];
    BOOST_REQUIRE(!p.p_z.back().empty());
    *std::max_element(p.p_z.back().begin(), p.p_z.back().end()) -= 0.01;  // sums to 0.99
    BOOST_CHECK_THROW(check_physical(p), std::invalid_argument);
    p = g.packs[0];
    p.p_z[0].push_back(-0.0);
    BOOST_CHECK_NO_THROW(check_physical(p));
    // Mean coordination above the kissing bound: Z = 1e9 was reported as 500000000.75.
    p = g.packs[0];
    p.scalars[scalar_index("z_mean_tol_1e-3")] = 1e9;
    BOOST_CHECK_EXCEPTION(check_physical(p), std::invalid_argument, [&](const auto& e) {
        return std::string(e.what()) ==
               p.source +
                   ": z_mean_tol_1e-3 = 1000000000.000000 is physically impossible (a sphere "
                   "of one size averages at most 12 contacts at this tolerance)";
    });
    p.scalars[scalar_index("z_mean_tol_1e-3")] = 12.0;
    BOOST_CHECK_NO_THROW(check_physical(p));
    p.scalars[scalar_index("z_mean_tol_1e-3")] = 12.01;
    BOOST_CHECK_THROW(check_physical(p), std::invalid_argument);
    p = g.packs[0];
    p.scalars[scalar_index("z_mean_tol_5e-2")] = 16.0;  // the cap-area bound at δ = 0.05
    BOOST_CHECK_NO_THROW(check_physical(p));
    p.scalars[scalar_index("z_mean_tol_5e-2")] = 16.5;
    BOOST_CHECK_THROW(check_physical(p), std::invalid_argument);
    p = g.packs[0];
    p.z_mean.at(0) = 13.0;  // the per-tolerance curve, Z(0)
    BOOST_CHECK_THROW(check_physical(p), std::invalid_argument);
    p = g.packs[0];
    p.provenance.emplace_back("size_modes", "1:0.5,0.5:0.5");  // several sizes: 24 at contact
    p.z_mean.at(0) = 20.0;
    BOOST_CHECK_NO_THROW(check_physical(p));
    p.z_mean.at(0) = 24.5;
    BOOST_CHECK_THROW(check_physical(p), std::invalid_argument);
    Group bad = g;
    bad.packs[0].scalars[scalar_index("phi")] = 2.864;  // a report from it is refused
    BOOST_CHECK_THROW(build_report({g, bad}, plan_of({{0, 1}})), std::invalid_argument);
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

// Plots hold at most 6 series: every reference chunk (≤ 3) meets every candidate chunk,
// each series lands in some plot, each plot mixes both kinds when both exist.
BOOST_AUTO_TEST_CASE(plots_are_split_into_at_most_six_series) {
    for (std::size_t candidates = 0; candidates <= 9; ++candidates) {
        for (std::size_t references = 0; references <= 7; ++references) {
            std::vector<bool> reference(candidates, false);
            reference.insert(reference.end(), references, true);
            const auto parts = split_series(reference);
            std::vector<std::size_t> seen(reference.size(), 0);
            for (const auto& part : parts) {
                BOOST_TEST(part.size() <= kMaxSeries);
                bool any_ref = false, any_cand = false;
                for (const std::size_t i : part) {
                    ++seen[i];
                    (reference[i] ? any_ref : any_cand) = true;
                }
                if (candidates > 0 && references > 0) {
                    BOOST_TEST((any_ref && any_cand));
                }
            }
            for (const std::size_t s : seen) {
                BOOST_TEST(s >= 1U);
            }
            if (candidates + references > 0 && candidates + references <= kMaxSeries &&
                references <= 3) {
                BOOST_TEST(parts.size() == 1U);  // a small plot stays whole
            }
        }
    }
}

// The DEM parameter table: the pours' recorded parameters per class, one value when they
// agree, all of them when they differ, "—" where one class lacks a key another has, and
// keys no pour records (or packs that are not pours) left out.
BOOST_AUTO_TEST_CASE(dem_parameters_come_from_the_pours_headers) {
    const auto pour = [](const std::string& e, const std::string& mu) {
        PackSummary p;
        p.provenance = {{"generator", "liggghts"}, {"youngs_modulus_pa", e}, {"friction", mu}};
        return p;
    };
    Report report;
    report.groups.push_back(Group{"DEM a", {pour("1e+09", "0.5"), pour("1e+09", "0.5")}});
    report.groups.push_back(Group{"DEM b", {pour("5e+08", "0.01"), pour("2e+09", "0.01")}});
    PackSummary sgmp;
    sgmp.provenance = {{"generator", "sgmp"}, {"youngs_modulus_pa", "7"}};
    report.groups.push_back(Group{"mode", {sgmp}});
    const DemParameterTable t = dem_parameter_table(report, {"DEM a", "DEM b", "mode"});
    BOOST_TEST((t.classes == std::vector<std::string>{"DEM a", "DEM b"}));
    const auto row = [&](const std::string& key) {
        const auto at = std::find(t.keys.begin(), t.keys.end(), key);
        BOOST_TEST_REQUIRE((at != t.keys.end()), key);
        return t.values[static_cast<std::size_t>(at - t.keys.begin())];
    };
    BOOST_TEST((row("youngs_modulus_pa") == std::vector<std::string>{"1e+09", "5e+08 / 2e+09"}));
    BOOST_TEST((row("friction") == std::vector<std::string>{"0.5", "0.01"}));
    BOOST_TEST((std::find(t.keys.begin(), t.keys.end(), "restitution") == t.keys.end()));
}
