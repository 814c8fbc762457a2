#include <boost/test/unit_test.hpp>
#include <cctype>
#include <sstream>

#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/report/baseline.hpp"
#include "sgmp/report/contact_windows.hpp"
#include "sgmp/report/crossval.hpp"
#include "sgmp/report/crossval_render.hpp"
#include "sgmp/report/manifest.hpp"
#include "sgmp/report/report_render.hpp"
#include "sgmp/report/species_matrix.hpp"
#include "sgmp/report/thesis_table.hpp"
#include "test_support.hpp"

using namespace sgmp;
using namespace sgmp::metrics;
using namespace sgmp::report;

namespace {

std::string manifest_error(const std::string& text) {
    std::istringstream in(text);
    try {
        read_manifest(in, "m.csv");
    } catch (const InputError& error) {
        return error.what();
    }
    return {};
}

const std::string kManifestHeader = "role,group,count,seed,seconds,path\n";

MetricRow metric(const std::string& name, double candidate, double reference, double tolerance) {
    MetricRow row;
    row.name = name;
    row.label = metric_rule(name).label;
    row.unit = metric_rule(name).unit;
    row.kind = metric_rule(name).kind;
    row.candidate_mean = candidate;
    row.reference_mean = reference;
    row.difference = candidate - reference;
    row.seed_spread = tolerance;
    row.tolerance = tolerance;
    row.tolerance_rule = "margin";
    row.margin = tolerance;
    row.ratio = std::abs(row.difference) / tolerance;
    row.verdict = *row.ratio <= 1.0 ? Verdict::Agree : Verdict::Differ;
    row.p_differ = row.verdict == Verdict::Differ ? 1e-4 : 0.9;  // a clear difference
    return row;
}

Comparison comparison(const std::string& candidate, const std::string& reference, std::size_t count,
                      double phi_c, double phi_r, double tol, double gr_ratio) {
    Comparison c;
    c.candidate = candidate;
    c.reference = reference;
    c.count = count;
    c.candidate_packs = 3;
    c.reference_packs = 3;
    for (const auto& rule : metric_rules()) {
        if (rule.name == "phi") {
            c.rows.push_back(metric("phi", phi_c, phi_r, tol));
        } else if (rule.name == "g_r") {
            c.rows.push_back(metric("g_r", gr_ratio, 0.0, 1.0));
        } else {
            c.rows.push_back(metric(rule.name, 5.0, 6.0, 0.3));
        }
    }
    return c;
}

/// Two arrangements against two friction classes at one count.
Report sample_report() {
    Report report;
    report.comparisons = {comparison("single-column", "DEM mu=0.5", 150, 0.60, 0.61, 0.02, 0.8),
                          comparison("single-column", "DEM mu=0.01", 150, 0.60, 0.64, 0.01, 2.5),
                          comparison("loose-random", "DEM mu=0.5", 150, 0.58, 0.61, 0.02, 1.5),
                          comparison("loose-random", "DEM mu=0.01", 150, 0.58, 0.64, 0.01, 3.0)};
    return report;
}

std::vector<ManifestEntry> sample_manifest() {
    std::istringstream in(kManifestHeader +
                          "candidate,single-column,150,1,0.002,a1.xyz\n"
                          "candidate,single-column,150,2,0.004,a2.xyz\n"
                          "candidate,loose-random,150,1,0.010,b1.xyz\n"
                          "reference,DEM mu=0.5,150,1,1.5,r1.xyz.gz\n"
                          "reference,DEM mu=0.01,150,1,2.5,r2.xyz.gz\n");
    return read_manifest(in, "m.csv");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(crossval)

BOOST_AUTO_TEST_CASE(manifest_is_read_strictly) {
    const auto entries = sample_manifest();
    BOOST_TEST(entries.size() == 5u);
    BOOST_TEST(entries[4].group == "DEM mu=0.01");
    BOOST_TEST(*entries[0].seconds == 0.002);
    BOOST_TEST(manifest_error("") ==
               "m.csv: empty manifest: expected the header 'role,group,count,seed,seconds,path'");
    BOOST_TEST(manifest_error(kManifestHeader) == "m.csv:1: the manifest lists no packs");
    BOOST_TEST(manifest_error(kManifestHeader + "judge,a,150,1,,p\n") ==
               "m.csv:2: role 'judge' must be 'candidate', 'reference', 'variant' or 'stiff'");
    BOOST_TEST(manifest_error(kManifestHeader + "candidate,a,many,1,,p\n") ==
               "m.csv:2: count 'many' must be a positive integer");
    BOOST_TEST(manifest_error(kManifestHeader + "candidate,a,150,1,-3,p\n") ==
               "m.csv:2: seconds '-3' must be a number >= 0 or empty");
    BOOST_TEST(manifest_error(kManifestHeader + "candidate,a,150,1,,p\ncandidate,a,150,2,,p\n") ==
               "m.csv:3: path 'p' is listed twice");
    BOOST_TEST(manifest_error(kManifestHeader + "candidate,a,150,1\n") ==
               "m.csv:2: expected 6 comma-separated fields, found 4");
}

BOOST_AUTO_TEST_CASE(groups_are_planned_every_candidate_against_every_reference) {
    const GroupPlan plan = plan_groups(sample_manifest());
    BOOST_TEST(plan.labels.size() == 4u);
    BOOST_TEST(plan.plan.comparisons.size() == 4u);
    BOOST_TEST(plan.plan.class_sets.front().size() == 2u);
    BOOST_TEST(plan.paths[0].size() == 2u);
    // A variant set is a reference class of its own (another protocol of the group it
    // names), compared with every candidate and in the class set; never a tolerance.
    std::istringstream with_variant(kManifestHeader +
                                    "candidate,a,150,1,,p1\nreference,R,150,1,,p2\n"
                                    "variant,R,150,1,,p3\n");
    const GroupPlan v = plan_groups(read_manifest(with_variant, "m"));
    BOOST_TEST(v.labels.size() == 3u);
    BOOST_TEST(v.labels[2] == "R (variant)");
    BOOST_TEST(v.plan.comparisons.size() == 2u);
    BOOST_TEST((v.plan.class_sets.front() == std::vector<std::size_t>{1, 2}));
    std::istringstream orphan(kManifestHeader +
                              "candidate,a,150,1,,p1\nreference,R,150,1,,p2\n"
                              "variant,S,150,1,,p3\n");
    BOOST_CHECK_THROW(plan_groups(read_manifest(orphan, "m")), std::invalid_argument);
    std::istringstream only_candidates(kManifestHeader + "candidate,a,150,1,,p\n");
    BOOST_CHECK_THROW(plan_groups(read_manifest(only_candidates, "m")), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(headline_carries_verdicts_and_the_thesis_beside_us) {
    std::istringstream thesis_csv(
        "arrangement,count,runtime_s,packing_fraction,table\nsingle-column,150,138,0.6160,5.1\n");
    std::istringstream starts_csv(
        "arrangement,count,grid,starting_height,table\nloose-random,150,,3.38,8.2\n");
    const ThesisTables thesis{read_thesis_results(thesis_csv, "results.csv"),
                              read_thesis_starts(starts_csv, "starting_packs.csv")};
    const CrossValidation cv = cross_validate(sample_report(), sample_manifest(), thesis);
    BOOST_TEST_REQUIRE(cv.rows.size() == 2u);
    const HeadlineRow& column = cv.rows[0];
    BOOST_TEST(column.group == "single-column");
    BOOST_TEST(*column.seconds == 0.003, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(*column.thesis_speedup == 46000.0, boost::test_tools::tolerance(1e-9));
    BOOST_TEST_REQUIRE(column.against.size() == 2u);
    BOOST_TEST(column.against[0].reference == "DEM mu=0.5");
    BOOST_TEST(column.against[0].row("phi").verdict == Verdict::Agree);  // |0.60 − 0.61| ≤ 0.02
    BOOST_TEST(column.against[1].row("phi").verdict == Verdict::Differ);  // |0.60 − 0.64| > 0.01
    BOOST_TEST(column.against[0].row("g_r").verdict == Verdict::Agree);
    BOOST_TEST(column.against[1].row("g_r").verdict == Verdict::Differ);
    BOOST_TEST(*column.against[0].speedup == 500.0, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(!cv.rows[1].thesis.has_value());
    BOOST_TEST(!column.thesis_start.has_value());
    BOOST_TEST(cv.rows[1].thesis_start->starting_height == 3.38);
    const std::string md = render_crossval_markdown(cv);
    // The stand-in lines, the verdict matrix (one mark per count), the headline and the
    // thesis table.
    BOOST_TEST(md.find("- **DEM mu=0.5**:\n  - **single-column** differs on ") != std::string::npos,
               md);
    // φ, Z and g(r) lead the differences; the largest follows when it is another metric.
    const std::size_t line = md.find("  - **single-column** differs on ");
    const std::string sentence = md.substr(line, md.find('\n', line) - line);
    BOOST_TEST(sentence.find("(17 of 19 tests differ family-wise") != std::string::npos, sentence);
    BOOST_TEST(sentence.find("); stands in at 0 of 1 counts") != std::string::npos, sentence);
    const KeptDifference lead = leading_difference(cv.stand_ins[0]);
    BOOST_TEST(sentence.find("differs on " + lead.label) != std::string::npos, sentence);
    BOOST_TEST(md.find("; 500× faster than the DEM pour at N = 150.") != std::string::npos);
    CrossValidation slow = cv;  // a mode slower than the pour is said to be slower
    BOOST_TEST_REQUIRE(!slow.stand_ins.empty());
    slow.stand_ins[0].speedup = 0.25;
    BOOST_TEST(render_crossval_markdown(slow).find("; 4× slower than the DEM pour at N = 150.") !=
               std::string::npos);
    BOOST_TEST(md.find("| single-column | DEM mu=0.5 | ✓ | ✗ |") != std::string::npos);
    BOOST_TEST(md.find("| 150 | single-column | 0.003 | 0.6000 | 5.00 | 5.00 | 5.000 | ✓✗✗✗✗✓ | "
                       "0.8 | 500× |") != std::string::npos);
    BOOST_TEST(
        md.find("| 150 | single-column | 0.0000 | 138 (5.1) | 0.003 | 46000× | 0.6160 | 0.6000 | "
                "-0.0160 | — | — |") != std::string::npos);
    const auto json = crossval_json(cv);
    BOOST_TEST(json["schema_version"] == kSchemaVersion);
    BOOST_TEST(json["headline"][0]["against"][1]["metrics"]["phi"]["verdict"] == "differ");
    const std::string csv = render_headline_csv(cv, "cmd");
    BOOST_TEST(csv.rfind("count,candidate,reference,metric,", 0) == 0u);  // header row first
    BOOST_TEST(csv.find("150,single-column,DEM mu=0.01,phi,0.6,0,0.64,0,0.01,4.0000000000000036,"
                        "differ,") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(tuned_comparisons_are_withheld_and_disclosed) {
    std::istringstream in(
        "group,parameter,value,reference,count,seeds,note\n"
        "loose-random,relax_friction,0.2,DEM mu=0.5,150,1-5 7,\"chosen from 0.1, 0.2\"\n");
    const auto tuning = read_tuning(in, "t.csv");
    BOOST_TEST_REQUIRE(tuning.size() == 1u);
    BOOST_TEST(tuning[0].seeds.size() == 6u);
    BOOST_TEST(tuning[0].note == "chosen from 0.1, 0.2");
    Report report = sample_report();
    const Verdict before = report.comparisons[2].row("phi").verdict;
    BOOST_TEST(withhold_tuned(report, tuning, sample_manifest()) == 1u);
    const MetricRow& phi = report.comparisons[2].row("phi");  // loose-random vs DEM mu=0.5
    BOOST_TEST(phi.verdict == Verdict::Info);
    BOOST_TEST(phi.tolerance_rule ==
               "tuned on these seeds (would be " + std::string(to_string(before)) + ")");
    BOOST_TEST(report.comparisons[3].row("phi").verdict == Verdict::Differ);  // other class
    // Seeds the tuning did not use are judged.
    std::istringstream other(
        "group,parameter,value,reference,count,seeds,note\n"
        "loose-random,relax_friction,0.2,DEM mu=0.5,150,2-3,\n");
    Report kept = sample_report();
    BOOST_TEST(withhold_tuned(kept, read_tuning(other, "t.csv"), sample_manifest()) == 0u);
    CrossValidation cv = cross_validate(report, sample_manifest(), {});
    cv.tuning = tuning;
    const std::string md = render_crossval_markdown(cv);
    // The answer comes first: one sentence per mode, before the stand-in details, the
    // tuned parameters and the DEM table.
    BOOST_TEST(md.find("## The answer\n") == 0u);
    BOOST_TEST(md.find("- **loose-random** (tuned): ") < md.find("## Which SGMP mode"));
    BOOST_TEST(md.find("## Which SGMP mode") < md.find("## Tuned parameters"));
    BOOST_TEST(md.find("- **loose-random** (tuned): relax_friction = 0.2, tuned against DEM "
                       "mu=0.5 at N = 150 (seeds 1 2 3 4 5 7); chosen from 0.1, 0.2.") !=
               std::string::npos);
    BOOST_TEST(md.find("**loose-random** (tuned) ") != std::string::npos);
    for (const char* bad :
         {"group,parameter,value,reference,count,seeds,note\na,p,1,R,0,1,\n",
          "group,parameter,value,reference,count,seeds,note\na,p,1,R,5,3-1,\n",
          "group,parameter,value,reference,count,seeds,note\n,p,1,R,5,1,\n", "group,parameter\n"}) {
        std::istringstream b(bad);
        BOOST_CHECK_THROW(read_tuning(b, "t.csv"), sgmp::InputError);
    }
}

BOOST_AUTO_TEST_CASE(a_relaxed_mode_partly_certified_says_so_and_not_that_it_is_unstable) {
    // loose-random relaxed, 2 packs at N = 150 with certificates, one of them not certified:
    // the answer counts the certified packs; it never reads Z as instability where
    // certificates decide (a certified pack is an equilibrium whatever its Z).
    Report report = sample_report();
    Group relaxed{"loose-random", {}};
    for (const char* certified : {"true", "false"}) {
        PackSummary p;
        p.count = 150;
        p.provenance = {{"relax", "frictional"}, {"certified", certified}};
        relaxed.packs.push_back(p);
    }
    report.groups.push_back(relaxed);
    const std::string md = render_crossval_markdown(cross_validate(report, sample_manifest(), {}));
    const auto line_start = md.find("- **loose-random**: ");
    BOOST_TEST_REQUIRE(line_start != std::string::npos);
    const std::string line = md.substr(line_start, md.find('\n', line_start) - line_start);
    BOOST_TEST(line.find("Certified equilibria (contact forces balance every sphere): at N = 150, "
                         "1 of 2 packs; a count with an uncertified pack is not judged.") !=
                   std::string::npos,
               line);
    BOOST_TEST(line.find("cannot be mechanically stable") == std::string::npos, line);
}

BOOST_AUTO_TEST_CASE(holm_keeps_what_the_step_down_rule_keeps) {
    // Holm at 5 % over 4 p-values: 0.01 ≤ 0.05/4 kept, 0.02 ≤ 0.05/3 fails: one rejection;
    // order does not matter.
    BOOST_TEST((holm_rejected({0.02, 0.01, 0.04, 0.5}, 0.05) == std::vector<std::size_t>{1}));
    BOOST_TEST(
        (holm_rejected({0.001, 0.012, 0.02, 0.04}, 0.05) == std::vector<std::size_t>{0, 1, 2, 3}));
    BOOST_TEST(holm_rejected({}, 0.05).empty());
    // A single differ that Holm does not keep leaves the pair undecided or standing in,
    // and is named; a kept one makes it differ.
    MetricRow agree = metric("phi", 0.60, 0.60, 0.01);
    MetricRow weak = metric("split_ratio", 0.70, 0.60, 0.03);
    weak.p_differ = 0.04;  // alone below 5 %, not below 5 %/2
    StandIn s = stand_in_from({{300, {agree, weak}}});
    BOOST_TEST(s.differ == 1u);
    BOOST_TEST(s.differ_familywise == 0u);
    BOOST_TEST(!s.stands_in());  // 1 of 2 judged agree: half is no majority
    BOOST_TEST(to_string(s.decision) == "undecided");
    BOOST_TEST(s.worst_metric == metric_rule("split_ratio").label);
    // An inconclusive metric counts as judged: 2 of 3 agree stands in, 1 of 3 does not.
    MetricRow open = metric("voronoi_phi_mean", 0.60, 0.60, 0.01);
    open.verdict = Verdict::Inconclusive;
    MetricRow agree_z = metric("z_mean_tol_1e-3", 4.8, 4.8, 0.3);
    BOOST_TEST(stand_in_from({{300, {agree, agree_z, open}}}).stands_in());
    BOOST_TEST(!stand_in_from({{300, {agree, open, open}}}).stands_in());
    const StandIn tallied = stand_in_from({{300, {agree, agree_z, open}}, {600, {agree, open}}});
    BOOST_TEST_REQUIRE(tallied.tallies.size() == 2u);
    BOOST_TEST(tallied.tallies[0].standing);
    BOOST_TEST((tallied.tallies[0].agree == 2u && tallied.tallies[0].judged == 3u));
    BOOST_TEST(!tallied.tallies[1].standing);
    BOOST_TEST(to_string(tallied.decision) == "undecided");
    weak.p_differ = 0.001;
    s = stand_in_from({{300, {agree, weak}}});
    BOOST_TEST(to_string(s.decision) == "differs");
}

BOOST_AUTO_TEST_CASE(baseline_takes_the_strictest_reference_tolerance) {
    const auto entries = baseline_entries(sample_report());
    BOOST_TEST_REQUIRE(entries.size() == 2u * 16u);  // 2 groups × 16 scalar metrics
    BOOST_TEST(entries[0].metric == "phi");
    BOOST_TEST(entries[0].value == 0.60);
    BOOST_TEST(entries[0].tolerance == 0.01);
    BOOST_TEST(entries[0].tolerance_source == "declared margin");
    for (const auto& e : entries) {
        BOOST_TEST(e.metric != "g_r");  // curves are not kept as values
    }
}

BOOST_AUTO_TEST_CASE(regression_passes_identical_runs_and_flags_moved_metrics) {
    const auto baseline = baseline_entries(sample_report());
    const auto round_trip = parse_baseline(
        nlohmann::json::parse(baseline_json(baseline, {{"tool", "t"}}).dump()), "b.json");
    BOOST_TEST(round_trip.size() == baseline.size());
    for (const auto& row : regress(round_trip, baseline)) {
        BOOST_TEST(row.pass);
    }
    auto moved = baseline;
    moved[0].value += 0.011;  // beyond the 0.01 tolerance
    moved[1].value += 0.29;   // within the 0.3 tolerance
    moved.pop_back();         // an entry disappears
    const auto rows = regress(baseline, moved);
    BOOST_TEST(!rows[0].pass);
    BOOST_TEST(rows[1].pass);
    BOOST_TEST(!rows.back().pass);
    BOOST_TEST(!rows.back().current.has_value());
    const std::string table = render_regression_table(rows, true);
    BOOST_TEST(table.find("missing") != std::string::npos);
    BOOST_TEST(table.find("FAIL") != std::string::npos);
    BOOST_CHECK_THROW(parse_baseline(nlohmann::json::parse(
                                         "{\"schema_version\": 2, \"entries\": [{\"group\": 1}]}"),
                                     "b.json"),
                      InputError);
    // A count must be a whole number as JSON holds it: 1e50, 150.5, 150.0 and -3 are refused
    // with one line naming the value (1e50 used to reach an undefined float conversion).
    for (const std::string count : {"1E50", "150.5", "150.0", "-3", "\"150\""}) {
        const std::string text =
            "{\"schema_version\": 2, \"entries\": [{\"group\": \"g\", \"count\": " + count +
            ", \"metric\": \"phi\", \"value\": 0.6, \"tolerance\": 0.01}]}";
        const std::string message = sgmp::testing::input_error_of(
            [&] { (void)parse_baseline(nlohmann::json::parse(text), "b.json"); });
        BOOST_TEST(message.find("b.json: entry 0 is malformed: count ") == 0, message);
        BOOST_TEST(message.find("must be a whole number >= 0") != std::string::npos, message);
    }
    // Fields of the wrong type are named, not reported in the JSON library's words
    // ("[json.exception.type_error.302] type must be string, but is number").
    const std::string wrong_type =
        "{\"schema_version\": 2, \"entries\": [{\"group\": 7, \"count\": 150, "
        "\"metric\": \"phi\", \"value\": 0.6, \"tolerance\": 0.01}]}";
    BOOST_TEST(sgmp::testing::input_error_of([&] {
                   (void)parse_baseline(nlohmann::json::parse(wrong_type), "b.json");
               }) == "b.json: entry 0 is malformed: 'group' must be a string");
    const std::string entry =
        "{\"group\": \"g\", \"count\": 150, \"metric\": \"phi\", \"value\": 0.6, "
        "\"tolerance\": 0.01}";
    const std::string good = "{\"schema_version\": 2, \"entries\": [" + entry + "]}";
    BOOST_TEST(parse_baseline(nlohmann::json::parse(good), "b.json").at(0).count == 150u);
    // A repeated entry (the last would have won, so a wrong first one passed) and a
    // missing or non-numeric schema_version are refused in one line.
    const std::string twice =
        "{\"schema_version\": 2, \"entries\": [" + entry + ", " + entry + "]}";
    BOOST_TEST(sgmp::testing::input_error_of([&] {
                   (void)parse_baseline(nlohmann::json::parse(twice), "b.json");
               }).find("entry 1 is malformed: it repeats group, count and metric of entry 0") !=
               std::string::npos);
    for (const std::string version :
         {"", "\"schema_version\": \"2\", ", "\"schema_version\": 99, "}) {
        const std::string text = "{" + version + "\"entries\": [" + entry + "]}";
        BOOST_TEST(sgmp::testing::input_error_of([&] {
                       (void)parse_baseline(nlohmann::json::parse(text), "b.json");
                   }).find("b.json: schema_version ") == 0u,
                   text);
    }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(markdown_html)

BOOST_AUTO_TEST_CASE(markdown_renders_through_md4c) {
    // Emphasis, code, lists and GitHub pipe tables; raw HTML is escaped, not passed through.
    const std::string html = sgmp::report::markdown_to_html(
        "## Head <1>\n\nSome **bold** and `code`.\n\n- item a\n- item b\n\n| x | verdict |\n"
        "| ---: | --- |\n| 1 | differ |\n");
    BOOST_TEST(html.find("<h2>Head &lt;1&gt;</h2>") != std::string::npos);
    BOOST_TEST(html.find("<strong>bold</strong>") != std::string::npos);
    BOOST_TEST(html.find("<code>code</code>") != std::string::npos);
    BOOST_TEST(html.find("<li>item b</li>") != std::string::npos);
    BOOST_TEST(html.find("<td>differ</td>") != std::string::npos);
    BOOST_TEST(html.find("**") == std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()

// The terminal headline fits 120 columns (code points), with every row of the model, and
// names each reference in its legend.
BOOST_AUTO_TEST_CASE(the_terminal_headline_fits_120_columns) {
    const CrossValidation cv = cross_validate(sample_report(), sample_manifest(), {});
    const std::string text = render_headline_text(cv);
    std::size_t rows = 0;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::size_t columns = 0;
        for (const unsigned char c : line) {
            columns += (c & 0xC0) != 0x80 ? 1 : 0;  // UTF-8: count the first byte of each
        }
        BOOST_TEST(columns <= 120u, line);
        rows += !line.empty() && std::isdigit(static_cast<unsigned char>(line.front())) ? 1 : 0;
    }
    BOOST_TEST(rows >= cv.rows.size());  // each row once per block of references
    for (const auto& reference : cv.references) {
        BOOST_TEST(text.find("] " + reference) != std::string::npos, reference);
    }
}

BOOST_AUTO_TEST_CASE(the_species_matrix_marks_each_species_row_and_counts_agreement) {
    // Hand-built: one mode against two classes at one count; the first comparison holds two
    // per-species rows (agree, differ) beside a whole-pack row, the second one of them
    // (inconclusive). Packs of equal spheres (no species rows) get no section.
    const auto row = [](const std::string& name, Verdict verdict) {
        MetricRow m;
        m.name = name;
        m.label = name;
        m.unit = "ratio";
        m.verdict = verdict;
        return m;
    };
    CrossValidation cv;
    cv.candidates = {"loose-random"};
    cv.references = {"DEM a", "DEM b"};
    cv.counts = {1002};
    HeadlineRow headline;
    headline.group = "loose-random";
    headline.count = 1002;
    headline.against.resize(2);
    headline.against[0].rows = {row("phi", Verdict::Differ),
                                row("species_1:voronoi_phi_mean", Verdict::Agree),
                                row("mixing_deviation_max", Verdict::Differ)};
    headline.against[1].rows = {row("phi", Verdict::Agree),
                                row("species_1:voronoi_phi_mean", Verdict::Inconclusive)};
    cv.rows = {headline};
    std::ostringstream md;
    species_matrix_markdown(md, cv);
    const std::string text = md.str();
    BOOST_TEST(text.find("## Per-species verdict matrix") != std::string::npos);
    BOOST_TEST(text.find("| loose-random | DEM a | ✓ | ✗ | 1 of 2 |") != std::string::npos);
    BOOST_TEST(text.find("| loose-random | DEM b | ◌ | · | 0 of 1 |") != std::string::npos);
    BOOST_TEST(text.find("phi |") == std::string::npos);  // whole-pack rows stay out
    cv.rows[0].against[0].rows = {row("phi", Verdict::Differ)};
    cv.rows[0].against[1].rows = {row("phi", Verdict::Agree)};
    std::ostringstream none;
    species_matrix_markdown(none, cv);
    BOOST_TEST(none.str().empty());
}

BOOST_AUTO_TEST_CASE(contact_windows_cover_every_pair_type_of_a_blend_and_nothing_else) {
    // Bimodal 1 : 0.5 at 1 : 8 in number: species diameters 1.8 and 0.9 number-mean d, so
    // pair types touch at 1.8, 1.35 and 0.9 d; windows [0.98, 1.1]·σ of each.
    const auto ranges = contact_ranges({1.8, 0.9}, 0.9, 1.8);
    BOOST_TEST(ranges.size() == 3U);
    BOOST_TEST(!outside_contact_windows(1.34, 1.36, ranges));  // the 1 : 0.5 peak
    BOOST_TEST(!outside_contact_windows(1.96, 1.98, ranges));  // 1.1·1.8 = 1.98 reached
    BOOST_TEST(outside_contact_windows(1.99, 2.01, ranges));
    BOOST_TEST(outside_contact_windows(1.50, 1.52, ranges));
    BOOST_TEST(!outside_contact_windows(1.755, 1.775, ranges));  // 0.98·1.8 = 1.764
    BOOST_TEST(outside_contact_windows(1.74, 1.76, ranges));
    // Equal spheres: none, so their g(r) test is the one of [1.1, 5]·d alone.
    BOOST_TEST(contact_ranges({}, 1.0, 1.0).empty());
    BOOST_TEST(contact_ranges({1.0}, 1.0, 1.0).empty());
    // Sizes without species: the whole span.
    const auto span = contact_ranges({}, 0.5, 2.0);
    BOOST_TEST(span.size() == 1U);
    BOOST_TEST(!outside_contact_windows(1.0, 1.02, span));
    BOOST_TEST(outside_contact_windows(2.2, 2.22, span));
}
