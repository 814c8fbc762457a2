// `sgmp render`: a real POV-Ray render of a 300-sphere pack has the requested size (read
// from the PNG's IHDR), a missing renderer is exit 1 and leaves no file, bad options are
// usage errors (exit 2), an existing output is kept without --force.

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sgmp/render/png_info.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

namespace {

using Run = sgmp::testing::CommandRun;

/// A scratch directory holding a 300-sphere pack made by the real `sgmp pack`; `run` runs
/// `ENV sgmp ARGS` there.
struct Scratch : sgmp::testing::ProgramScratch {
    Scratch()
        : ProgramScratch(
              "render-cli-" + boost::unit_test::framework::current_test_case().p_name.get(),
              SGMP_EXECUTABLE) {
        BOOST_REQUIRE(run("pack --count 300 --arrangement loose-random --seed 2 --out '" +
                          path("p.xyz") + "'")
                          .status == 0);
    }
};

bool one_line(const std::string& text) {
    return !text.empty() && text.find('\n') == text.size() - 1;
}

}  // namespace

BOOST_AUTO_TEST_CASE(renders_a_png_of_the_requested_size) {
    const Scratch s;
    const Run r = s.run("render '" + s.path("p.xyz") + "' --out '" + s.path("p.png") +
                        "' --size 96x64 --view 20,25 --cut half --colour height --threads 1");
    BOOST_TEST_REQUIRE(r.status == 0, r.err);
    const std::string png = sgmp::testing::read_bytes(s.path("p.png"));
    const auto size = sgmp::render::png_size(png);
    BOOST_TEST_REQUIRE(size.has_value());
    BOOST_TEST(size->width == 96U);
    BOOST_TEST(size->height == 64U);
    BOOST_TEST(png.find("sgmp render") != std::string::npos);  // provenance tEXt
    BOOST_TEST(png.find("seed=2") != std::string::npos);
    // No scratch file or temporary is left beside the output.
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(s.dir)) {
        files += entry.path().filename().string().find(".tmp") == std::string::npos ? 1 : 0;
    }
    BOOST_TEST(files == 4U);  // p.xyz, p.png, stdout, stderr
    // An existing output is kept without --force (exit 2), replaced with it.
    BOOST_TEST(s.run("render '" + s.path("p.xyz") + "' --out '" + s.path("p.png") + "'").status ==
               2);
    BOOST_TEST(sgmp::testing::read_bytes(s.path("p.png")) == png);
    // The structure colourings render (their values: sphere_values_match_a_brute_count…).
    for (const char* colour : {"z", "local-phi"}) {
        const Run c = s.run("render '" + s.path("p.xyz") + "' --out '" + s.path("c.png") +
                            "' --size 96x64 --force --threads 1 --colour " + colour);
        BOOST_TEST(c.status == 0, colour << ": " << c.err);
    }
}

BOOST_AUTO_TEST_CASE(a_missing_renderer_is_exit_1_and_no_file) {
    const Scratch s;
    const Run r =
        s.run("render '" + s.path("p.xyz") + "' --out '" + s.path("p.png") + "'", "SGMP_POVRAY=");
    BOOST_TEST(r.status == 1);
    BOOST_TEST(one_line(r.err), r.err);
    BOOST_TEST(r.err.rfind("sgmp: povray was not found", 0) == 0, r.err);
    BOOST_TEST(!fs::exists(s.path("p.png")));
    // A renderer that fails: exit 1, one line, no file.
    const Run f = s.run("render '" + s.path("p.xyz") + "' --out '" + s.path("p.png") + "'",
                        "SGMP_POVRAY=/bin/false");
    BOOST_TEST(f.status == 1);
    BOOST_TEST(one_line(f.err), f.err);
    BOOST_TEST(!fs::exists(s.path("p.png")));
    // A renderer killed by a signal says so (it was reported as "povray failed (exit 0)").
    { std::ofstream(s.path("killed-povray")) << "#!/bin/sh\nkill -KILL $$\n"; }
    fs::permissions(s.path("killed-povray"), fs::perms::owner_all);
    const Run k = s.run("render '" + s.path("p.xyz") + "' --out '" + s.path("p.png") + "'",
                        "SGMP_POVRAY='" + s.path("killed-povray") + "'");
    BOOST_TEST(k.status == 1);
    BOOST_TEST(one_line(k.err), k.err);
    BOOST_TEST(k.err.rfind("sgmp: povray was killed by signal 9 (Killed)", 0) == 0, k.err);
    BOOST_TEST(!fs::exists(s.path("p.png")));
}

BOOST_AUTO_TEST_CASE(bad_options_are_usage_errors) {
    const Scratch s;
    const std::string base = "render '" + s.path("p.xyz") + "' --out '" + s.path("p.png") + "' ";
    for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
             {"--size 10x10", "sgmp: --size 10x10: must be WIDTHxHEIGHT"},
             {"--view 0,95", "sgmp: --view 0,95: must be AZ,EL"},
             {"--colour pink",
              "sgmp: --colour pink: must be one of bin, height, species, z, local-phi"},
             {"--cut 'q>1'", "sgmp: --cut q>1: must be none, half, slice"},
             {"--container box", "sgmp: --container box: must be one of outline"}}) {
        const Run r = s.run(base + args);
        BOOST_TEST(r.status == 2, args);
        BOOST_TEST(one_line(r.err), r.err);
        BOOST_TEST(r.err.rfind(expected, 0) == 0, r.err);
        BOOST_TEST(!fs::exists(s.path("p.png")));
    }
    const Run missing =
        s.run("render '" + s.path("none.xyz") + "' --out '" + s.path("p.png") + "'");
    BOOST_TEST(missing.status == 1);
    BOOST_TEST(one_line(missing.err), missing.err);
}
