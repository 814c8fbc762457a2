// Measurement split from comparison: `sgmp-compare report` (and crossval, by the same
// path) from measure's *.metrics.json gives the report of the packs themselves; from batch
// summary rows (--metrics) it gives the same scalar verdicts and leaves what the rows lack
// inconclusive.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/report/precomputed.hpp"
#include "sgmp/report/report_plots.hpp"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The lines of a report file without those recording the command line.
std::string without_command(const fs::path& path) {
    std::istringstream in(slurp(path));
    std::string kept;
    for (std::string line; std::getline(in, line);) {
        if (line.find("command") == std::string::npos &&
            line.find("sgmp-compare report --") == std::string::npos) {
            kept += line + "\n";
        }
    }
    return kept;
}

/// report.csv rows by metric name (fields joined as written).
std::map<std::string, std::vector<std::string>> rows_by_metric(const fs::path& path) {
    std::istringstream in(slurp(path));
    std::map<std::string, std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#' || line.rfind("count,", 0) == 0) {
            continue;
        }
        std::vector<std::string> fields;
        std::stringstream s(line);
        for (std::string f; std::getline(s, f, ',');) {
            fields.push_back(f);
        }
        rows[fields.at(3)] = fields;
    }
    return rows;
}

/// A scratch directory in which commands run, their stderr appended to `errors`.
struct Workspace {
    fs::path dir;
    std::string in;  ///< "cd DIR && "
    std::string sgmp = std::string("'") + SGMP_EXECUTABLE + "'";
    std::string compare = std::string("'") + SGMP_COMPARE_EXECUTABLE + "'";

    explicit Workspace(const std::string& name)
        : dir(fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()))),
          in("cd '" + dir.string() + "' && ") {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    [[nodiscard]] int run(const std::string& command) const {
        return std::system((in + command + " >/dev/null 2>>errors").c_str());
    }
};

}  // namespace

BOOST_AUTO_TEST_CASE(reports_from_precomputed_metrics) {
    const Workspace w("sgmp-precomputed");
    const fs::path& dir = w.dir;
    const std::string& in = w.in;
    const std::string& sgmp = w.sgmp;
    const std::string& compare = w.compare;
    const auto run = [&w](const std::string& command) { return w.run(command); };
    BOOST_REQUIRE(run(sgmp +
                      " batch --seeds 1-3 --count 250 --arrangement loose-random,small-dense "
                      "--out-pattern 'packs/{arrangement}-{seed}.xyz' --measure "
                      "--progress-seconds 0") == 0);
    BOOST_REQUIRE(run(compare + " measure packs/*.xyz --out m --no-voronoi") == 0);
    const std::string a =
        "packs/loose-random-1.xyz packs/loose-random-2.xyz packs/loose-random-3.xyz";
    const std::string b = "packs/small-dense-1.xyz packs/small-dense-2.xyz packs/small-dense-3.xyz";
    const std::string b_metrics =
        "m/small-dense-1.metrics.json m/small-dense-2.metrics.json "
        "m/small-dense-3.metrics.json";
    BOOST_REQUIRE(run(compare + " report --no-voronoi --out packs-report --a " + a + " --b " + b) ==
                  0);
    BOOST_REQUIRE(run(compare +
                      " report --no-voronoi --out json-report --a m/loose-random-1.metrics.json "
                      "m/loose-random-2.metrics.json m/loose-random-3.metrics.json --b " +
                      b_metrics) == 0);
    // From measure's outputs: every file as from the packs, but for the command line.
    for (const char* file : {"report.csv", "report.json", "report.md"}) {
        BOOST_TEST(without_command(dir / "packs-report" / file) ==
                       without_command(dir / "json-report" / file),
                   file);
    }
    for (const auto& entry : fs::directory_iterator(dir / "packs-report" / "plots")) {
        BOOST_TEST(
            slurp(entry.path()) == slurp(dir / "json-report" / "plots" / entry.path().filename()),
            entry.path().filename());
    }
    // From batch rows: the scalars they hold give the same means; the rest is not judged.
    BOOST_REQUIRE(run(compare +
                      " report --no-voronoi --out rows-report --metrics summary.csv --a " + a +
                      " --b " + b_metrics) == 0);
    const auto packs = rows_by_metric(dir / "packs-report/report.csv");
    const auto rows = rows_by_metric(dir / "rows-report/report.csv");
    for (const char* metric : {"phi", "z_mean_tol_0", "z_mean_tol_1e-2", "overlaps"}) {
        BOOST_TEST(rows.at(metric) == packs.at(metric), metric);
    }
    // The batch's g(r) reaches 2.1 d, measure's 5 d: the density cancels in the split ratio,
    // which agrees to rounding (relative 1e-12 is far above the 1e-15 seen).
    BOOST_TEST(std::stod(rows.at("split_ratio").at(7)) == std::stod(packs.at("split_ratio").at(7)),
               boost::test_tools::tolerance(1e-12));
    for (const char* metric : {"q6_global", "g_r", "p_z_tol_1e-2", "voronoi_phi_mean"}) {
        BOOST_TEST(rows.at(metric).at(19) == "inconclusive", metric);  // the verdict column
        BOOST_TEST(rows.at(metric).at(16) == "not measured", metric);
    }
    // Both sides from batch rows: nothing to draw for g(r), P(Z) or φ(y), so those plots are
    // left out (an empty g(r) plot made gnuplot fail, "plots skipped"); Z(δ) is drawn.
    BOOST_REQUIRE(run(compare + " report --no-voronoi --out rows-only --metrics summary.csv --a " +
                      a + " --b " + b) == 0);
    std::vector<std::string> drawn;
    for (const auto& entry : fs::directory_iterator(dir / "rows-only" / "plots")) {
        if (entry.path().extension() == ".svg") {
            drawn.push_back(entry.path().filename().string());
        }
    }
    if (sgmp::report::find_gnuplot()) {
        BOOST_TEST(drawn == std::vector<std::string>{"c0_N250_zdelta.svg"},
                   boost::test_tools::per_element());
    }
    BOOST_TEST(slurp(dir / "errors").empty(), slurp(dir / "errors"));
    // A metrics file whose P(Z) is not an array is refused naming the entry (it was
    // "[json.exception.type_error.302] type must be array, but is string").
    for (const char* kind : {"g_r", "phi_y", "p_z", "voronoi_phi"}) {
        fs::copy_file(dir / "m" / (std::string("loose-random-1.") + kind + ".csv"),
                      dir / "m" / (std::string("bad.") + kind + ".csv"));
    }
    auto json = nlohmann::ordered_json::parse(slurp(dir / "m/loose-random-1.metrics.json"));
    json["p_z"]["0"] = "abc";
    std::ofstream(dir / "m/bad.metrics.json") << json.dump();
    const int status = std::system((in + compare +
                                    " report --no-voronoi --out bad-report --a m/bad.metrics.json "
                                    "m/loose-random-2.metrics.json --b " +
                                    b_metrics + " >/dev/null 2>bad-errors")
                                       .c_str());
    BOOST_TEST(WEXITSTATUS(status) == 1);
    BOOST_TEST(slurp(dir / "bad-errors") ==
               "sgmp-compare: m/bad.metrics.json: 'p_z' entry '0' must be an array of numbers, "
               "not string\n");
    fs::remove_all(dir);
}

// Contact metrics of SGMP rows against DEM pours: the summary's overlap_mean gives the
// same "below overlap depth" as measuring the packs; a summary written before that column
// leaves them unjudged ("overlap depth not known"). Both were judged, and differed, when
// the depth was unknown.
BOOST_AUTO_TEST_CASE(contact_metrics_from_batch_rows_follow_the_overlap_depth) {
    const Workspace w("sgmp-depth");
    const fs::path& dir = w.dir;
    const std::string& sgmp = w.sgmp;
    const std::string& compare = w.compare;
    const auto run = [&w](const std::string& command) { return w.run(command); };
    BOOST_REQUIRE(run(sgmp + " batch --seeds 1-3 --count 150 --arrangement loose-random "
                             "--out-pattern 'packs/s{seed}.xyz' --measure --progress-seconds 0") ==
                  0);
    std::string dem;
    std::string dem_metrics;
    for (int seed = 1; seed <= 3; ++seed) {
        const std::string stem = "n0150-mu0.5-seed" + std::to_string(seed);
        dem += " '" + std::string(SGMP_SOURCE_DIR) + "/data/reference/" + stem + ".xyz.gz'";
        dem_metrics += " m/" + stem + ".metrics.json";
    }
    BOOST_REQUIRE(run(compare + " measure" + dem + " --out m --no-voronoi") == 0);
    const std::string a = " --a packs/s1.xyz packs/s2.xyz packs/s3.xyz --b" + dem_metrics;
    BOOST_REQUIRE(run(compare + " report --no-voronoi --out packs-report" + a) == 0);
    BOOST_REQUIRE(
        run(compare + " report --no-voronoi --out rows-report --metrics summary.csv" + a) == 0);
    // The summary of before: the same rows without the overlap_mean column.
    std::istringstream summary(slurp(dir / "summary.csv"));
    std::ofstream old(dir / "old.csv");
    std::size_t column = 0;
    for (std::string line; std::getline(summary, line);) {
        std::vector<std::string> fields;
        std::stringstream split(line);
        for (std::string f; std::getline(split, f, ',');) {
            fields.push_back(f);
        }
        if (line.rfind("job,", 0) == 0) {
            column = static_cast<std::size_t>(
                std::find(fields.begin(), fields.end(), "overlap_mean") - fields.begin());
            BOOST_REQUIRE(column < fields.size());
        }
        if (line[0] != '#') {
            fields.erase(fields.begin() + static_cast<std::ptrdiff_t>(column));
        }
        std::string kept;
        for (const auto& f : fields) {
            kept += (kept.empty() ? "" : ",") + f;
        }
        old << (line[0] == '#' ? line : kept) << "\n";
    }
    old.close();
    BOOST_REQUIRE(run(compare + " report --no-voronoi --out old-report --metrics old.csv" + a) ==
                  0);
    const auto packs = rows_by_metric(dir / "packs-report/report.csv");
    const auto rows = rows_by_metric(dir / "rows-report/report.csv");
    const auto before = rows_by_metric(dir / "old-report/report.csv");
    // Columns 16 and 19: tolerance_rule and verdict.
    for (const char* metric : {"z_mean_tol_1e-6", "z_mean_tol_1e-3"}) {
        BOOST_TEST(packs.at(metric).at(19) == "info", metric);  // SGMP 0 against DEM ~10⁻³ d
        BOOST_TEST(packs.at(metric).at(16) == "below overlap depth", metric);
        BOOST_TEST(rows.at(metric).at(19) == "info", metric);
        BOOST_TEST(rows.at(metric).at(16) == "below overlap depth", metric);
    }
    BOOST_TEST(rows.at("z_mean_tol_1e-2") == packs.at("z_mean_tol_1e-2"));
    for (const char* metric : {"z_mean_tol_1e-3", "z_mean_tol_1e-2"}) {
        BOOST_TEST(before.at(metric).at(19) == "info", metric);
        BOOST_TEST(before.at(metric).at(16) == "overlap depth not known", metric);
    }
    BOOST_TEST(slurp(dir / "errors").empty(), slurp(dir / "errors"));
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(batch_rows_without_metrics_or_packs_are_refused) {
    const std::string header =
        "job,count,seed,seconds,measure_seconds,phi,z_0,z_1e-6,z_1e-3,z_1e-2,z_2e-2,z_5e-2,"
        "overlaps,overlap_max,wall_overlaps,split_ratio,voronoi_phi_mean,path\n";
    const auto rows = sgmp::report::summaries_from_batch(
        header + "0,10,1,0.1,0.1,0.5,1,2,3,4,5,6,0,0,0,0.7,,p.xyz\n", "s.csv");
    BOOST_REQUIRE(rows.size() == 1u);
    BOOST_TEST(rows[0].first == "p.xyz");
    BOOST_TEST(rows[0].second.scalar("z_mean_tol_1e-2") == 4.0);
    BOOST_TEST(std::isnan(rows[0].second.scalar("q6_global")));
    BOOST_TEST(!rows[0].second.has_curves());
    BOOST_CHECK_THROW(
        sgmp::report::summaries_from_batch(header + "0,10,1,0.1,,,,,,,,,,,,,,p.xyz\n", "s.csv"),
        sgmp::InputError);  // made without --measure
    BOOST_CHECK_THROW(sgmp::report::summaries_from_batch(
                          header + "0,10,1,0.1,0.1,0.5,1,2,3,4,5,6,0,0,0,0.7,,\n", "s.csv"),
                      sgmp::InputError);  // made with --no-packs
    BOOST_CHECK_THROW(sgmp::report::summaries_from_batch("a,b\n1,2\n", "s.csv"), sgmp::InputError);
    // A measured metric that is NaN or infinite was taken for "not measured" (an empty
    // field) and reported as 0.0000.
    for (const char* phi : {"nan", "NaN", "inf", "-inf"}) {
        const std::string row =
            std::string("0,10,1,0.1,0.1,") + phi + ",1,2,3,4,5,6,0,0,0,0.7,,p.xyz\n";
        try {
            (void)sgmp::report::summaries_from_batch(header + row, "s.csv");
            BOOST_ERROR("phi " << phi << " was accepted");
        } catch (const sgmp::InputError& e) {
            BOOST_TEST(e.what() == "s.csv:2: 'phi' is '" + std::string(phi) +
                                       "': a measured value must be finite (a metric not "
                                       "measured is an empty field)");
        }
    }
    BOOST_CHECK_THROW(sgmp::report::summaries_from_batch(
                          header + "0,10,1,0.1,0.1,0.5,1,2,nan,4,5,6,0,0,0,0.7,,p.xyz\n", "s.csv"),
                      sgmp::InputError);
    // Counts that are no particle count (the first was a fuzz finding: its cast to size_t
    // was undefined behaviour).
    for (const char* count : {"66666666666666666660", "1e26", "0", "-3", "10.5", "nan"}) {
        const std::string row =
            std::string("0,") + count + ",1,0.1,0.1,0.5,1,2,3,4,5,6,0,0,0,0.7,,p.xyz\n";
        try {
            (void)sgmp::report::summaries_from_batch(header + row, "s.csv");
            BOOST_ERROR("count " << count << " was accepted");
        } catch (const sgmp::InputError& e) {
            BOOST_TEST(std::string(e.what()).find("s.csv:2: count ") == 0, e.what());
        }
    }
}

// A metrics file whose keys hold the wrong JSON type printed nlohmann's
// "[json.exception.type_error.302]" text; a schema_version far beyond int (fuzz findings,
// tests/fuzz/corpus/metrics_json/schema_version_*) was converted to int: undefined
// behaviour. Each is now one line naming the file, the key and the type expected.
BOOST_AUTO_TEST_CASE(metrics_files_of_the_wrong_shape_are_refused_in_one_line) {
    const auto error_of = [](const std::string& text) {
        try {
            (void)sgmp::report::summary_from_measure("m.metrics.json",
                                                     nlohmann::ordered_json::parse(text), "", "",
                                                     nlohmann::ordered_json());
        } catch (const sgmp::InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    const std::string not_metrics =
        "m.metrics.json: is not a metrics file of schema_version 2 (sgmp-compare measure)";
    BOOST_TEST(error_of(R"({"schema_version":"2"})") ==
               "m.metrics.json: 'schema_version' must be a whole number, not string");
    BOOST_TEST(error_of(R"({"schema_version":null})") ==
               "m.metrics.json: 'schema_version' must be a whole number, not null");
    BOOST_TEST(error_of(R"({"schema_version":[2]})") ==
               "m.metrics.json: 'schema_version' must be a whole number, not array");
    BOOST_TEST(error_of("null") == not_metrics);
    BOOST_TEST(error_of("[2]") == not_metrics);
    BOOST_TEST(error_of(R"({"schema_version":218356777100.5710})") ==
               not_metrics + "; its schema_version is 218356777100.571");
    BOOST_TEST(error_of(R"({"schema_version":5555555555555555555555555555555555552})")
                   .find(not_metrics + "; its schema_version is ") == 0u);
    BOOST_TEST(error_of(R"({"schema_version":2.5})") ==
               not_metrics + "; its schema_version is 2.5");
    BOOST_TEST(error_of(R"({"schema_version":2,"provenance":5})") ==
               "m.metrics.json: 'provenance' must be an object, not number");
    BOOST_TEST(error_of(R"({"schema_version":2,"provenance":{"input":5}})") ==
               "m.metrics.json: 'provenance.input' must be a string, not number");
    BOOST_TEST(error_of(R"({"schema_version":2,"provenance":{"input_metadata":[1]}})") ==
               "m.metrics.json: 'provenance.input_metadata' must be an object, not array");
}
