// No container is ever guessed (sgmp/pack/stated_container.hpp): a stored DEM pour written
// as a LAMMPS dump with its box at the walls, and again with the box 0.075 wider on each
// side (as LIGGGHTS scripts with walls as fixes inside a larger box write it), measures
// exactly as the extended XYZ original once its walls are stated (--container or a manifest
// column), and is refused when they are not. Suites: `container` (one N = 1002 pour, in
// process), `container_every_count` (every count of the reference set; slow) and
// `container_cli` (sgmp-compare and sgmp convert; cli).

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sgmp/metrics/measure.hpp"
#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/stated_container.hpp"
#include "sgmp/report/manifest.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace sgmp;

namespace {

const fs::path kReference = fs::path(SGMP_SOURCE_DIR) / "data" / "reference";
const fs::path kCompare = fs::path(SGMP_BINARY_DIR) / "compare" / "sgmp-compare";
const fs::path kSgmp = fs::path(SGMP_BINARY_DIR) / "sgmp" / "sgmp";
/// How much wider than the walls the foreign box is, on each side and below the floor.
constexpr double kWider = 0.075;
const std::string kWalls = "-0.625 0.625 -0.625 0.625 -0.625";

std::string pour_name(int count, const char* mu, int seed) {
    std::string n = std::to_string(count);
    n.insert(0, 4 - n.size(), '0');
    return "n" + n + "-mu" + mu + "-seed" + std::to_string(seed);
}

/// A LIGGGHTS-style `dump custom` of `pack` (no walls stated), its box the container's
/// walls and floor widened by `wider`, up to above the top sphere.
std::string foreign_dump(const Pack& pack, double wider) {
    const Container c;
    double top = c.floor;
    for (const Particle& p : pack.particles) {
        top = std::max(top, p.center.y() + p.radius);
    }
    std::ostringstream out;
    out << "ITEM: TIMESTEP\n123456\nITEM: NUMBER OF ATOMS\n"
        << pack.particles.size() << "\nITEM: BOX BOUNDS ff ff ff\n"
        << format_number(c.x_min - wider) << ' ' << format_number(c.x_max + wider) << '\n'
        << format_number(c.floor - wider) << ' ' << format_number(top + wider) << '\n'
        << format_number(c.z_min - wider) << ' ' << format_number(c.z_max + wider) << '\n'
        << "ITEM: ATOMS id type x y z vx vy vz radius\n";
    for (const Particle& p : pack.particles) {
        out << p.id << " 1 " << format_number(p.center.x()) << ' ' << format_number(p.center.y())
            << ' ' << format_number(p.center.z()) << " 0 0 0 " << format_number(p.radius) << '\n';
    }
    return out.str();
}

/// Every metric of a measurement (the per-pack JSON and the g(r) curve), without where
/// the container came from.
std::string metrics_text(const Pack& pack) {
    const metrics::Measurement m = metrics::measure(pack, metrics::MeasureOptions{});
    nlohmann::ordered_json j = metrics::metrics_json(m, nlohmann::ordered_json::object());
    j.erase("container_source");
    std::ostringstream g_r;
    metrics::write_g_r_csv(g_r, m, nlohmann::ordered_json::object());
    return j.dump(1) + "\n" + g_r.str();
}

/// The pour `name` from the reference set, at the walls and 0.075 wider: the same metrics
/// as the original when stated (or, at the walls, reached), refused when not.
void check_pour(const std::string& name, const fs::path& dir) {
    const Pack original = read_pack_file(kReference / (name + ".xyz.gz"));
    BOOST_TEST_REQUIRE(original.metadata.get("container").value_or("") == kWalls);
    const std::string expected = metrics_text(original);
    std::ofstream(dir / (name + "-walls.dump")) << foreign_dump(original, 0.0);
    std::ofstream(dir / (name + "-wide.dump")) << foreign_dump(original, kWider);

    const Pack at_walls = read_pack_file(dir / (name + "-walls.dump"));
    BOOST_TEST(at_walls.metadata.get("container_from").value_or("") == "box", name);
    BOOST_TEST(metrics_text(at_walls) == expected, name + " at the walls");

    const std::string refused =
        testing::input_error_of([&] { read_pack_file(dir / (name + "-wide.dump")); });
    BOOST_TEST(
        refused.find("-wide.dump: no container stated, and the spheres keep ") != std::string::npos,
        refused);
    BOOST_TEST(refused.find("--container") != std::string::npos);
    ReadOptions stated;
    stated.container = StatedContainer{Container::parse(kWalls), "--container"};
    const Pack wide = read_pack_file(dir / (name + "-wide.dump"), stated).pack;
    BOOST_TEST(metrics_text(wide) == expected, name + " 0.075 wider, stated");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(container)

BOOST_AUTO_TEST_CASE(a_wider_box_measures_as_the_walls_once_they_are_stated) {
    const testing::TestDirectory scratch("container-1002");
    check_pour(pour_name(1002, "0.5", 1), scratch.path());
}

BOOST_AUTO_TEST_CASE(the_manifest_may_state_each_pack_s_container) {
    std::istringstream old_style("role,group,count,seed,seconds,path\nreference,a,2,1,,a.xyz\n");
    const auto plain = report::read_manifest(old_style, "m.csv");
    BOOST_TEST(!plain.at(0).container.has_value());
    std::istringstream with(
        "role,group,count,seed,seconds,path,container\n"
        "reference,a,2,1,,a.dump,-0.625 0.625 -0.625 0.625 -0.625\n"
        "reference,a,2,2,,b.xyz,\n"
        "candidate,b,2,1,,\"c,1.dump\",\"-1 1 -2 2 -3\"\n");
    const auto entries = report::read_manifest(with, "m.csv");
    BOOST_TEST_REQUIRE(entries.size() == 3U);
    BOOST_TEST(entries[0].container.value_or(Container{0, 1, 0, 1, 0}).to_string() == kWalls);
    BOOST_TEST(entries[0].line == 2U);
    BOOST_TEST(!entries[1].container.has_value());
    BOOST_TEST(entries[2].container.value_or(Container{}).to_string() == "-1 1 -2 2 -3");
    BOOST_TEST(entries[2].path == "c,1.dump");
    const auto error = [](const std::string& text) {
        return testing::input_error_of([&] {
            std::istringstream in(text);
            (void)report::read_manifest(in, "m.csv");
        });
    };
    const std::string header = "role,group,count,seed,seconds,path,container\n";
    BOOST_TEST(error(header + "reference,a,2,1,,a.dump,0 1 0 1\n") ==
               "m.csv:2: container '0 1 0 1': must be five finite numbers: x_min x_max z_min "
               "z_max floor");
    BOOST_TEST(error(header + "reference,a,2,1,,a.dump,1 0 0 1 0\n") ==
               "m.csv:2: container '1 0 0 1 0': must have x_min < x_max and z_min < z_max "
               "(x_min x_max z_min z_max floor)");
    BOOST_TEST(error(header + "reference,a,2,1,,a.dump\n") ==
               "m.csv:2: expected 7 comma-separated fields, found 6");
}

BOOST_AUTO_TEST_SUITE_END()

// Every count of the reference set, both friction classes (seed 1): slow, run only when
// named (CTest compare_container_every_count_tests, label slow).
BOOST_AUTO_TEST_SUITE(container_every_count, *boost::unit_test::disabled())

BOOST_AUTO_TEST_CASE(every_count_measures_as_the_walls_once_they_are_stated) {
    const testing::TestDirectory scratch("container-every-count");
    for (const int count : {150, 300, 750, 1002, 2001, 3000, 6000, 9000}) {
        for (const char* mu : {"0.5", "0.01"}) {
            check_pour(pour_name(count, mu, 1), scratch.path());
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()

// The command lines: sgmp-compare measure, crossval (--container and the manifest column)
// and sgmp convert on the N = 1002 pours.
BOOST_AUTO_TEST_SUITE(container_cli)

namespace {

const fs::path& cli_scratch() {
    static const testing::TestDirectory dir("container-cli");
    return dir.path();
}

testing::CommandRun run(const fs::path& tool, const std::string& arguments) {
    return testing::run_command(
        "cd '" + cli_scratch().string() + "' && '" + tool.string() + "' " + arguments,
        cli_scratch());
}

void write(const std::string& name, const std::string& text) {
    std::ofstream(cli_scratch() / name) << text;
}

/// The text of `path` in the scratch directory without its `#` comment lines (provenance).
std::string without_comments(const std::string& path) {
    std::istringstream in(testing::read_bytes(cli_scratch() / path));
    std::string line;
    std::string kept;
    while (std::getline(in, line)) {
        if (line.rfind('#', 0) != 0) {
            kept += line + '\n';
        }
    }
    return kept;
}

/// A metrics.json's metrics, without the provenance and where the container came from.
std::string measured(const std::string& path) {
    auto j = nlohmann::ordered_json::parse(testing::read_bytes(cli_scratch() / path));
    for (const char* key : {"provenance", "container_source", "source", "input"}) {
        j.erase(key);
    }
    return j.dump(1);
}

/// The N = 1002 pours (both classes, seeds 1 and 2) as originals (`o-*.xyz.gz`) and as
/// dumps 0.075 wider (`w-*.dump`).
void prepare() {
    for (const char* mu : {"0.5", "0.01"}) {
        for (const int seed : {1, 2}) {
            const std::string name = pour_name(1002, mu, seed);
            fs::copy_file(kReference / (name + ".xyz.gz"),
                          cli_scratch() / ("o-" + name + ".xyz.gz"),
                          fs::copy_options::overwrite_existing);
            write("w-" + name + ".dump",
                  foreign_dump(read_pack_file(kReference / (name + ".xyz.gz")), kWider));
        }
    }
}

/// A manifest of the four pours: candidates μ = 0.5 as `candidate_prefix` files, references
/// μ = 0.01 as originals; `container` (if not empty) in a last column of the candidates.
std::string manifest(const std::string& candidate_prefix, const std::string& candidate_ending,
                     const std::string& container) {
    std::string text = std::string("role,group,count,seed,seconds,path") +
                       (container.empty() ? "" : ",container") + "\n";
    for (const int seed : {1, 2}) {
        text += "candidate,DEM 0.5,1002," + std::to_string(seed) + ",," + candidate_prefix +
                pour_name(1002, "0.5", seed) + candidate_ending +
                (container.empty() ? "" : "," + container) + "\n";
    }
    for (const int seed : {1, 2}) {
        text += "reference,DEM 0.01,1002," + std::to_string(seed) + ",,o-" +
                pour_name(1002, "0.01", seed) + ".xyz.gz" + (container.empty() ? "" : ",") + "\n";
    }
    return text;
}

}  // namespace

BOOST_AUTO_TEST_CASE(measure_refuses_an_unreached_box_and_takes_stated_walls) {
    prepare();
    const std::string wide = "w-" + pour_name(1002, "0.5", 1) + ".dump";
    const std::string original = "o-" + pour_name(1002, "0.5", 1) + ".xyz.gz";
    const auto refused = run(kCompare, "measure " + wide + " --out m-refused");
    BOOST_TEST(refused.status == 1);
    BOOST_TEST(refused.err.find("sgmp-compare: " + wide +
                                ": no container stated, and the spheres keep 0.486 d") == 0U,
               refused.err);
    BOOST_TEST(refused.err.find("--container") != std::string::npos);
    BOOST_TEST(std::count(refused.err.begin(), refused.err.end(), '\n') == 1);
    BOOST_TEST(!fs::exists(cli_scratch() / "m-refused"));

    const auto stated =
        run(kCompare, "measure " + wide + " --container '" + kWalls + "' --out m-w");
    BOOST_TEST_REQUIRE(stated.status == 0, stated.err);
    BOOST_TEST_REQUIRE(run(kCompare, "measure " + original + " --out m-o").status == 0);
    const std::string stem = pour_name(1002, "0.5", 1);
    BOOST_TEST(measured("m-w/w-" + stem + ".metrics.json") ==
               measured("m-o/o-" + stem + ".metrics.json"));
    BOOST_TEST(without_comments("m-w/w-" + stem + ".g_r.csv") ==
               without_comments("m-o/o-" + stem + ".g_r.csv"));
    const auto source = nlohmann::json::parse(testing::read_bytes(
        cli_scratch() / ("m-w/w-" + stem + ".metrics.json")))["container_source"];
    BOOST_TEST(source.get<std::string>() == "--container");

    // A bad --container: status 2, one line naming the option and the rule.
    for (const char* bad : {"0 1 0 1", "0 1 0 1 nan", "1 0 0 1 0", "0 1 1 1 0"}) {
        const auto usage =
            run(kCompare, "measure " + original + " --container '" + bad + "' --out m-bad");
        BOOST_TEST(usage.status == 2, bad);
        BOOST_TEST(
            usage.err.find("sgmp-compare: --container '" + std::string(bad) + "': must ") == 0U,
            usage.err);
        BOOST_TEST(std::count(usage.err.begin(), usage.err.end(), '\n') == 1);
    }
    // Walls that leave out a centre: the sphere named, status 1.
    const auto outside = run(kCompare, "measure " + wide +
                                           " --container '-0.5 0.625 -0.625 0.625 "
                                           "-0.625' --out m-out");
    BOOST_TEST(outside.status == 1);
    BOOST_TEST(outside.err.find(": sphere id ") != std::string::npos, outside.err);
    BOOST_TEST(outside.err.find("lies outside the container '-0.5 0.625") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(measure_refuses_a_box_periodic_on_every_axis) {
    // pp pp pp: no floor for the bed's metrics; refused in one line, status 1, nothing written.
    write("all-periodic.dump",
          "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n"
          "0 6\n0 6\n0 6\nITEM: ATOMS id x y z radius\n1 1 1.3 1 0.5\n2 3 4.3 3 0.5\n");
    const auto refused = run(kCompare, "measure all-periodic.dump --out m-periodic");
    BOOST_TEST(refused.status == 1);
    BOOST_TEST(refused.err.find("periodic in y too") != std::string::npos, refused.err);
    BOOST_TEST(std::count(refused.err.begin(), refused.err.end(), '\n') == 1);
    BOOST_TEST(!fs::exists(cli_scratch() / "m-periodic"));
}

BOOST_AUTO_TEST_CASE(crossval_takes_the_walls_from_the_option_or_the_manifest) {
    prepare();
    write("originals.csv", manifest("o-", ".xyz.gz", ""));
    write("column.csv", manifest("w-", ".dump", "\"" + kWalls + "\""));
    write("unstated.csv", manifest("w-", ".dump", ""));
    const auto originals =
        run(kCompare, "crossval --manifest originals.csv --no-pictures --out cv-o");
    BOOST_TEST_REQUIRE(originals.status == 0, originals.err);
    const auto column = run(kCompare, "crossval --manifest column.csv --no-pictures --out cv-c");
    BOOST_TEST_REQUIRE(column.status == 0, column.err);
    const auto option = run(kCompare, "crossval --manifest unstated.csv --container '" + kWalls +
                                          "' --no-pictures --out cv-opt");
    BOOST_TEST_REQUIRE(option.status == 0, option.err);
    const std::string expected = without_comments("cv-o/report.csv");
    BOOST_TEST(expected.find("split_ratio") != std::string::npos);
    BOOST_TEST(without_comments("cv-c/report.csv") == expected);
    BOOST_TEST(without_comments("cv-opt/report.csv") == expected);

    const auto refused = run(kCompare, "crossval --manifest unstated.csv --no-pictures --out cv-r");
    BOOST_TEST(refused.status == 1);
    BOOST_TEST(refused.err.find(".dump: no container stated, and the spheres keep 0.") !=
                   std::string::npos,
               refused.err);
    BOOST_TEST(!fs::exists(cli_scratch() / "cv-r"));

    // A manifest container that contradicts the pack's own header: one line, status 1.
    std::string contradicting = manifest("o-", ".xyz.gz", "");
    contradicting.replace(contradicting.find("path\n"), 5, "path,container\n");
    for (std::size_t at = contradicting.find(".xyz.gz\n"); at != std::string::npos;
         at = contradicting.find(".xyz.gz\n", at + 1)) {
        contradicting.insert(at + 7, ",-0.7 0.7 -0.7 0.7 -0.7");
    }
    write("contradicting.csv", contradicting);
    const auto contradiction =
        run(kCompare, "crossval --manifest contradicting.csv --no-pictures --out cv-x");
    BOOST_TEST(contradiction.status == 1);
    BOOST_TEST(contradiction.err.find("contradicts the file's own container '" + kWalls + "'") !=
                   std::string::npos,
               contradiction.err);
    BOOST_TEST(std::count(contradiction.err.begin(), contradiction.err.end(), '\n') == 1);
    // The option and a row that state other walls contradict each other.
    const auto both = run(kCompare,
                          "crossval --manifest column.csv --container '-1 1 -1 1 -1' "
                          "--no-pictures --out cv-b");
    BOOST_TEST(both.status == 1);
    BOOST_TEST(both.err.find("column.csv:2: container '" + kWalls +
                             "' contradicts --container '-1 1 -1 1 -1'") != std::string::npos,
               both.err);
}

BOOST_AUTO_TEST_CASE(convert_keeps_the_stated_walls) {
    prepare();
    const std::string wide = "w-" + pour_name(1002, "0.5", 1) + ".dump";
    const auto refused = run(kSgmp, "convert " + wide + " c.xyz");
    BOOST_TEST(refused.status == 1);
    BOOST_TEST(refused.err.find("sgmp convert: " + wide + ": no container stated") == 0U,
               refused.err);
    BOOST_TEST(run(kSgmp, "convert " + wide + " c.xyz --container '0 1 0 1'").status == 2);
    const auto ok = run(kSgmp, "convert " + wide + " c.xyz --container '" + kWalls + "' --force");
    BOOST_TEST_REQUIRE(ok.status == 0, ok.err);
    const Pack xyz = read_pack_file(cli_scratch() / "c.xyz");
    BOOST_TEST(xyz.metadata.get("container").value_or("") == kWalls);
    BOOST_TEST(xyz.metadata.get("container_from").value_or("") == "--container");
    // Our own dumps and data files carry their walls: they read back without a statement.
    for (const char* out : {"c.dump", "c.data"}) {
        BOOST_TEST_REQUIRE(run(kSgmp, std::string("convert c.xyz ") + out + " --force").status ==
                           0);
        BOOST_TEST(
            read_pack_file(cli_scratch() / out).metadata.get("container").value_or("") == kWalls,
            out);
    }
}

BOOST_AUTO_TEST_SUITE_END()
