// The command line: bad input gives one line on stderr and a non-zero status (2 for usage),
// and never leaves a half-written output directory.

#include <boost/test/unit_test.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>
#include <vector>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/report/manifest.hpp"
#include "synthetic_packs.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kTool = fs::path(SGMP_BINARY_DIR) / "compare" / "sgmp-compare";

/// One scratch directory for the whole suite (the cases build on each other's files).
const fs::path& scratch() {
    static const sgmp::testing::TestDirectory dir("compare-cli");
    return dir.path();
}

using Result = sgmp::testing::CommandRun;

/// Runs `sgmp-compare ARGUMENTS` in the scratch directory.
Result run(const std::string& arguments) {
    return sgmp::testing::run_command(
        "cd '" + scratch().string() + "' && '" + kTool.string() + "' " + arguments, scratch());
}

void write(const std::string& name, const std::string& text) {
    std::ofstream(scratch() / name) << text;
}

std::size_t lines(const std::string& text) {
    std::size_t n = 0;
    for (const char c : text) {
        n += c == '\n' ? 1 : 0;
    }
    return n;
}

const std::string kHeader =
    "Properties=id:I:1:pos:R:3:radius:R:1:color:I:1 pbc=\"F F F\" generator=test\n";

void good_pack(const std::string& name, std::uint64_t seed) {
    sgmp::write_pack_file(scratch() / name, sgmp::testing::jittered_fcc_pack(300, 1.05, 0.02, seed),
                          true);
}

/// A stand-in DEM pour: a jittered lattice with the seed and Young's modulus of a pour.
void pour_pack(const std::string& name, std::uint64_t seed, double spacing, double youngs) {
    sgmp::Pack pack = sgmp::testing::jittered_fcc_pack(300, spacing, 0.02, seed);
    pack.metadata.set_integer("seed", static_cast<long long>(seed));
    if (youngs > 0.0) {
        pack.metadata.set_number("youngs_modulus_pa", youngs);
    }
    sgmp::write_pack_file(scratch() / name, pack, true);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(cli)

BOOST_AUTO_TEST_CASE(crossval_judges_a_stiff_set_as_a_class_of_its_own) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        const std::string s = std::to_string(seed);
        good_pack("h" + s + ".xyz", seed);
        pour_pack("soft" + s + ".xyz", seed, 1.06, 1e9);
        pour_pack("stiff" + s + ".xyz", seed, 1.05, 1.6e10);
    }
    write("limit.csv",
          "role,group,count,seed,seconds,path\n"
          "candidate,relaxed,300,1,0.1,h1.xyz\ncandidate,relaxed,300,2,0.1,h2.xyz\n"
          "reference,DEM mu=0,300,1,20,soft1.xyz\nreference,DEM mu=0,300,2,20,soft2.xyz\n"
          "stiff,DEM mu=0,300,1,,stiff1.xyz\nstiff,DEM mu=0,300,2,,stiff2.xyz\n");
    const Result ok = run("crossval --manifest limit.csv --no-pictures --out cv-limit");
    BOOST_TEST_REQUIRE(ok.status == 0, ok.err);
    const std::string md = sgmp::testing::read_bytes(scratch() / "cv-limit" / "report.md");
    BOOST_TEST(md.find("hard-sphere limit") == std::string::npos);  // no extrapolation
    BOOST_TEST(md.find("**DEM mu=0** against **DEM mu=0 (stiff)**") != std::string::npos);
    const std::string csv = sgmp::testing::read_bytes(scratch() / "cv-limit" / "report.csv");
    BOOST_TEST(csv.find("300,relaxed,DEM mu=0 (stiff),phi,") != std::string::npos);
    BOOST_TEST(csv.find(",verdict,margin,ci_low,ci_high,mdd,") != std::string::npos);
    // A manifest count that contradicts its file: one line, status 1, no report.
    write("wrong-count.csv",
          "role,group,count,seed,seconds,path\n"
          "candidate,relaxed,200,1,0.1,h1.xyz\ncandidate,relaxed,300,2,0.1,h2.xyz\n"
          "reference,DEM mu=0,300,1,20,soft1.xyz\nreference,DEM mu=0,300,2,20,soft2.xyz\n");
    const Result wrong = run("crossval --manifest wrong-count.csv --no-pictures --out cv-wrong");
    BOOST_TEST(wrong.status == 1);
    BOOST_TEST(lines(wrong.err) == 1u, wrong.err);
    BOOST_TEST(wrong.err.find("h1.xyz: the manifest says 200 spheres, the pack holds 300") !=
                   std::string::npos,
               wrong.err);
    BOOST_TEST(!fs::exists(scratch() / "cv-wrong"));
}

// Labels a user sets (manifest groups, --label-a/--label-b; report refuses quotes in its
// labels) reach gnuplot as literal text: backquotes, system(), quotes and @macros run
// nothing and break nothing.
BOOST_AUTO_TEST_CASE(labels_never_reach_a_shell_through_gnuplot) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        good_pack("la" + std::to_string(seed) + ".xyz", seed);
        good_pack("lb" + std::to_string(seed) + ".xyz", seed + 10);
    }
    for (const char* name : {"PWNED_A", "PWNED_B", "PWNED_C", "PWNED_D"}) {
        fs::remove(scratch() / name);
    }
    const Result report =
        run("report --a la1.xyz la2.xyz --b lb1.xyz lb2.xyz --label-a 'x`touch PWNED_A`' "
            "--label-b 'system(touch PWNED_B) @x' --out labels-report --force");
    BOOST_TEST(report.status == 0, report.err);
    write("labels.csv",
          "role,group,count,seed,seconds,path\n"
          "candidate,r`touch PWNED_C`'s @x,300,1,,la1.xyz\n"
          "candidate,r`touch PWNED_C`'s @x,300,2,,la2.xyz\n"
          "reference,\"q\"\"`touch PWNED_D`\",300,1,,lb1.xyz\n"
          "reference,\"q\"\"`touch PWNED_D`\",300,2,,lb2.xyz\n");
    const Result cv = run("crossval --manifest labels.csv --no-pictures --out labels-cv --force");
    BOOST_TEST(cv.status == 0, cv.err);
    for (const char* name : {"PWNED_A", "PWNED_B", "PWNED_C", "PWNED_D"}) {
        BOOST_TEST(!fs::exists(scratch() / name), name << " was created by gnuplot");
    }
    // The plots were drawn, with the labels as text.
    bool drawn = false;
    for (const auto& entry : fs::directory_iterator(scratch() / "labels-cv" / "plots")) {
        const std::string svg = sgmp::testing::read_bytes(entry.path());
        drawn = drawn || svg.find("touch PWNED_C") != std::string::npos;
    }
    BOOST_TEST(drawn);
}

// Past `ulimit -f` a write fails like a full disk: one line, status 1, no temporary
// (SIGXFSZ used to kill the tool with signal 25 and leave .m.tmp-PID/).
BOOST_AUTO_TEST_CASE(a_file_size_limit_fails_like_a_full_disk) {
    const std::string pour =
        std::string(SGMP_SOURCE_DIR) + "/data/reference/n3000-mu0.5-seed1.xyz.gz";
    fs::remove_all(scratch() / "limited");
    const Result r = sgmp::testing::run_command(
        "cd '" + scratch().string() + "' && ulimit -f 4 && '" + kTool.string() + "' measure '" +
            pour + "' --no-voronoi --out limited",
        scratch());
    BOOST_TEST(r.status == 1, r.err);
    BOOST_TEST(lines(r.err) == 1u, r.err);
    BOOST_TEST(r.err.rfind("sgmp-compare: ", 0) == 0u, r.err);
    // It names the output and the reason, not the temporary ("./.limited.tmp-PID.HOST/…:
    // cannot write", a path already removed).
    BOOST_TEST(r.err.rfind("sgmp-compare: limited/n3000-mu0.5-seed1.", 0) == 0u, r.err);
    BOOST_TEST(r.err.find(": write failed: File too large\n") != std::string::npos, r.err);
    BOOST_TEST(r.err.find(".tmp-") == std::string::npos, r.err);
    BOOST_TEST(!fs::exists(scratch() / "limited"));
    for (const auto& entry : fs::directory_iterator(scratch())) {
        BOOST_TEST(entry.path().filename().string().rfind(".limited.tmp", 0) != 0u, entry.path());
    }
}

// An endless line (/dev/zero) is refused at 16 MiB, under a 1 GB address-space limit (it
// used to grow until the memory limit, then fail with std::bad_alloc).
BOOST_AUTO_TEST_CASE(an_endless_input_is_refused_within_bounded_memory) {
    const Result r =
        sgmp::testing::run_command("cd '" + scratch().string() + "' && ulimit -v 1000000 && '" +
                                       kTool.string() + "' measure /dev/zero --out z",
                                   scratch());
    BOOST_TEST(r.status == 1, r.err);
    BOOST_TEST(r.err ==
                   "sgmp-compare: /dev/zero:1: line longer than 16777216 bytes (the "
                   "readers' limit)\n",
               r.err);
    BOOST_TEST(!fs::exists(scratch() / "z"));
}

BOOST_AUTO_TEST_CASE(bad_pack_files_give_one_line_and_status_1) {
    write("empty.xyz", "");
    write("short.xyz", "3\n" + kHeader + "1 0 0 0 0.05 0\n2 0.2 0 0 0.05 0\n");
    write("word.xyz", "1\n" + kHeader + "1 0 zero 0 0.05 0\n");
    write("columns.xyz", "1\n" + kHeader + "1 0 0 0 0.05\n");
    write("nan.xyz", "1\n" + kHeader + "1 0 nan 0 0.05 0\n");
    write("inf.xyz", "1\n" + kHeader + "1 0 inf 0 0.05 0\n");
    write("radius.xyz", "1\n" + kHeader + "1 0 0 0 -0.05 0\n");
    write("zero.xyz", "1\n" + kHeader + "1 0 0 0 0 0\n");
    write("container.xyz",
          "1\nProperties=id:I:1:pos:R:3:radius:R:1:color:I:1 container=\"1 2 3\"\n"
          "1 0 0 0 0.05 0\n");
    // Two spheres in one place: the Voronoi cell of one is empty (a content error, once
    // reported with the usage status 2).
    write("swallowed.xyz", "2\n" + kHeader + "1 0 0 0 0.05 0\n2 0 0 0 0.05 0\n");
    // A radius of 1e160 leaves g(r) no space for centres (once status 2, as for an option).
    write("huge.xyz", "1\n" + kHeader + "1 0 0 0 1e160 0\n");
    for (const char* file :
         {"empty.xyz", "short.xyz", "word.xyz", "columns.xyz", "nan.xyz", "inf.xyz", "radius.xyz",
          "zero.xyz", "container.xyz", "missing.xyz", "swallowed.xyz", "huge.xyz"}) {
        const Result r = run(std::string("measure ") + file + " --out out-bad");
        BOOST_TEST(r.status == 1, file << ": " << r.err);
        BOOST_TEST(lines(r.err) == 1u, file << ": " << r.err);
        BOOST_TEST(r.err.find(file) != std::string::npos, r.err);
        BOOST_TEST(!fs::exists(scratch() / "out-bad"));
    }
}

BOOST_AUTO_TEST_CASE(header_prints_the_provenance_keys_scripts_read) {
    write("keys.xyz",
          "1\nProperties=id:I:1:pos:R:3:radius:R:1:color:I:1 generator=test seed=7 "
          "label=\"a b\"\n1 0 0 0 0.05 0\n");
    const Result both = run("header keys.xyz seed label");
    BOOST_TEST(both.status == 0);
    BOOST_TEST(both.out == "7\na b\n");
    const Result allowed = run("header keys.xyz seed absent --allow-missing");
    BOOST_TEST(allowed.status == 0);
    BOOST_TEST(allowed.out == "7\n\n");
    BOOST_TEST(run("header keys.xyz absent").status == 1);   // a missing key is an input error
    write("cut.xyz", "2\n" + kHeader + "1 0 0 0 0.05 0\n");  // truncated: not reusable
    BOOST_TEST(run("header cut.xyz generator").status == 1);
    const Result r = run("header keys.xyz absent");
    BOOST_TEST(r.err == "sgmp-compare: keys.xyz:2: the header has no key 'absent'\n");
}

BOOST_AUTO_TEST_CASE(usage_errors_give_status_2) {
    good_pack("a.xyz", 1);
    good_pack("b.xyz", 2);
    const std::vector<std::string> bad{
        "measure a.xyz",                                               // no --out
        "measure a.xyz --out o --region 0 1 0 1",                      // 4 numbers
        "measure a.xyz --out o --region -0.7 0.5 -0.5 0.5 -0.5 0.5",   // through a wall
        "measure a.xyz --out o --region 0.5 -0.5 -0.5 0.5 -0.5 0.5",   // inverted
        "measure a.xyz --out o --gr-bin 0",                            // not positive
        "measure a.xyz --out o --gr-bin 6",                            // wider than range
        "measure a.xyz --out o --slab x",                              // not a number
        "measure a.xyz dir/a.xyz --out o",                             // same output names
        "report --a a.xyz --b b.xyz --label-a X --label-b X --out o",  // same labels
        "report --a a.xyz --out o",                                    // no --b
        "report --a a.xyz a.xyz --b b.xyz c.xyz --out o",              // one pack twice
        "report --a a.xyz --b b.xyz ./a.xyz --out o",                  // the same, respelt
        "measure a.xyz --out o --slab 1e15",                           // beyond 1e6 d
        "frobnicate",
    };
    for (const auto& arguments : bad) {
        const Result r = run(arguments);
        BOOST_TEST(r.status == 2, arguments << ": " << r.err);
        BOOST_TEST(lines(r.err) == 1u, arguments << ": " << r.err);
        BOOST_TEST(!fs::exists(scratch() / "o"), arguments);
    }
}

BOOST_AUTO_TEST_CASE(no_option_or_pack_allocates_without_bound) {
    good_pack("a.xyz", 1);
    // A sphere a billion sides up: default slabs of 1 d would number about 10^10.
    write("tall.xyz", "2\n" + kHeader + "1 0 0 0 0.05 0\n2 0 1e9 0 0.05 0\n");
    const std::vector<std::pair<std::string, std::string>> bad{
        {"measure a.xyz --out o --slab 1e-12",
         "sgmp-compare: --slab 1e-12: must be at least 0.001 d"},
        {"measure a.xyz --out o --gr-range 1e6 --gr-bin 100",
         "sgmp-compare: --gr-range 1e+06: must be at most 100 d"},
        {"measure a.xyz --out o --q6-cutoff 1e9",
         "sgmp-compare: --q6-cutoff 1e+09: must be at most 10"},
        {"measure a.xyz --out o --threads 4294967295",
         "sgmp-compare: --threads: must be a number in [0, 256] (0: all cores)"},
        {"measure tall.xyz --out o",
         "sgmp-compare: tall.xyz: --slab 1: gives 10000000007 slabs from the floor to the top "
         "sphere; at most 1000000 are allowed"},
    };
    for (const auto& [arguments, message] : bad) {
        const Result r = run(arguments);
        BOOST_TEST(r.status == 2, arguments << ": " << r.err);
        BOOST_TEST(r.err.substr(0, message.size()) == message, arguments << ": " << r.err);
        BOOST_TEST(lines(r.err) == 1u, arguments << ": " << r.err);
        BOOST_TEST(!fs::exists(scratch() / "o"), arguments);
    }
}

BOOST_AUTO_TEST_CASE(a_crafted_header_is_refused_and_leaves_no_temporary) {
    // Once an out-of-bounds read (SIGSEGV) that left a .m.tmp-PID directory behind.
    write("crafted.xyz", "1\nProperties=foo:R:5:pos:R:3:radius:R:1:bar:R:4294967287\n\n");
    const Result r = run("measure crafted.xyz --out m");
    BOOST_TEST(r.status == 1, r.err);
    BOOST_TEST(r.err.find("sgmp-compare: crafted.xyz:2: Properties entry 'bar' has count") == 0u,
               r.err);
    BOOST_TEST(lines(r.err) == 1u);
    for (const auto& entry : fs::directory_iterator(scratch())) {
        BOOST_TEST(entry.path().filename().string().find(".m.tmp-") == std::string::npos);
    }
}

BOOST_AUTO_TEST_CASE(sigint_removes_the_temporary_directory_and_exits_130) {
    // Three packs of 200,000 spheres take seconds to read and measure; SIGINT comes as
    // soon as the temporary output directory exists.
    const sgmp::Pack big = sgmp::testing::jittered_fcc_pack(200000, 1.05, 0.02, 5);
    for (const char* name : {"big1.xyz", "big2.xyz", "big3.xyz"}) {
        sgmp::write_pack_file(scratch() / name, big, true);
    }
    const std::string command =
        "cd '" + scratch().string() + "' && { '" + kTool.string() +
        "' measure big1.xyz big2.xyz big3.xyz --out big 2>stderr.txt & pid=$!; "
        "for i in $(seq 1000); do [ -d .big.tmp-$pid.\"$(hostname)\" ] && break; sleep 0.01; done; "
        "kill -INT $pid; wait $pid; echo $? >status.txt; }";
    BOOST_TEST(std::system(command.c_str()) == 0);
    BOOST_TEST(sgmp::testing::read_bytes(scratch() / "status.txt") == "130\n");
    BOOST_TEST(sgmp::testing::read_bytes(scratch() / "stderr.txt") ==
               "sgmp-compare: interrupted by SIGINT; its temporary files are removed\n");
    BOOST_TEST(!fs::exists(scratch() / "big"));
    for (const auto& entry : fs::directory_iterator(scratch())) {
        BOOST_TEST(entry.path().filename().string().find(".big.tmp-") == std::string::npos);
    }
}

BOOST_AUTO_TEST_CASE(manifest_paths_may_hold_commas_and_quotes) {
    std::istringstream in(
        "role,group,count,seed,seconds,path\n"
        "candidate,g,150,1,0.5,\"out, \"\"x y\"\"/a.xyz\"\n"
        "reference,\"DEM, mu=0.5\",150,1,,plain/b.xyz\n");
    const auto entries = sgmp::report::read_manifest(in, "m.csv");
    BOOST_TEST_REQUIRE(entries.size() == 2u);
    BOOST_TEST(entries[0].path == "out, \"x y\"/a.xyz");
    BOOST_TEST(entries[1].group == "DEM, mu=0.5");
    BOOST_TEST(entries[1].path == "plain/b.xyz");
    std::istringstream open_quote("role,group,count,seed,seconds,path\ncandidate,g,150,1,,\"a\n");
    std::string message;
    try {
        (void)sgmp::report::read_manifest(open_quote, "m.csv");
    } catch (const sgmp::InputError& error) {
        message = error.what();
    }
    BOOST_TEST(message == "m.csv:2: a quoted field lacks its closing quote or has text after it");
}

BOOST_AUTO_TEST_CASE(a_manifest_with_seconds_nan_is_refused) {
    std::istringstream in("role,group,count,seed,seconds,path\ncandidate,g,150,1,nan,a.xyz\n");
    std::string message;
    try {
        (void)sgmp::report::read_manifest(in, "m.csv");
    } catch (const sgmp::InputError& error) {
        message = error.what();
    }
    BOOST_TEST(message == "m.csv:2: seconds 'nan' must be a number >= 0 or empty");
}

BOOST_AUTO_TEST_CASE(measure_and_report_write_complete_directories) {
    good_pack("a.xyz", 1);
    good_pack("b.xyz", 2);
    good_pack("c.xyz", 3);
    BOOST_TEST(run("measure a.xyz b.xyz --out m").status == 0);
    for (const char* file :
         {"a.metrics.json", "a.g_r.csv", "a.phi_y.csv", "a.p_z.csv", "b.metrics.json"}) {
        BOOST_TEST(fs::exists(scratch() / "m" / file), file);
    }
    const std::string text = sgmp::testing::read_bytes(scratch() / "m" / "a.metrics.json");
    for (const char* key :
         {"\"count\"", "\"diameter\"", "\"phi\"", "\"overlaps\"", "\"overlap_max_over_d\"",
          "\"z_mean_tol_0\"", "\"z_mean_tol_1e-6\"", "\"z_mean_tol_1e-3\"", "\"z_mean_tol_1e-2\"",
          "\"z_mean_tol_2e-2\"", "\"z_mean_tol_5e-2\"", "\"q6_global\"", "\"q6_local_mean\"",
          "\"region\"", "\"sgmp-compare\""}) {
        BOOST_TEST(text.find(key) != std::string::npos, key);
    }
    // A directory typed with a trailing slash is the same directory.
    BOOST_TEST(run("measure a.xyz --out m-slash/").status == 0);
    BOOST_TEST(fs::exists(scratch() / "m-slash" / "a.metrics.json"));
    // Kept without --force, replaced with it; same inputs give the same bytes.
    BOOST_TEST(run("measure a.xyz --out m").status == 2);
    BOOST_TEST(run("measure a.xyz --out m/").status == 2);
    BOOST_TEST(run("measure a.xyz b.xyz --out m2 --threads 1").status == 0);
    const std::string text2 = sgmp::testing::read_bytes(scratch() / "m2" / "a.metrics.json");
    BOOST_TEST(text2.find("\"phi\"") != std::string::npos);
    BOOST_TEST(run("measure a.xyz --out m --force").status == 0);
    BOOST_TEST(!fs::exists(scratch() / "m" / "b.metrics.json"));
    // The same command gives the same bytes, whatever the thread count.
    const std::string first = sgmp::testing::read_bytes(scratch() / "m" / "a.metrics.json");
    const std::string curve = sgmp::testing::read_bytes(scratch() / "m" / "a.g_r.csv");
    BOOST_TEST(run("measure a.xyz --out m --force --threads 1").status == 0);
    BOOST_TEST(run("measure a.xyz --out m --force").status == 0);
    BOOST_TEST(sgmp::testing::read_bytes(scratch() / "m" / "a.metrics.json") == first);
    BOOST_TEST(sgmp::testing::read_bytes(scratch() / "m" / "a.g_r.csv") == curve);
    // --force replaces only what measure wrote: never the directory its packs are in, and
    // never the current directory, however it is spelled (it once deleted all of it).
    for (const std::string out : {"\"$PWD\"", ".", "./", "\"$PWD/..\""}) {
        const Result here = run("measure a.xyz --out " + out + " --force");
        BOOST_TEST(here.status == 1, out);
        BOOST_TEST(lines(here.err) == 1u, here.err);
        BOOST_TEST(here.err.find("sgmp-compare: ") == 0u, here.err);
        BOOST_TEST(here.err.find("current directory") != std::string::npos, here.err);
    }
    BOOST_TEST(fs::exists(scratch() / "a.xyz"));
    BOOST_TEST(fs::exists(scratch() / "m" / "a.metrics.json"));
    fs::create_directories(scratch() / "packs");
    fs::copy_file(scratch() / "a.xyz", scratch() / "packs" / "a.xyz",
                  fs::copy_options::overwrite_existing);
    const Result packs = run("measure packs/a.xyz --out packs --force");
    BOOST_TEST(packs.status == 1);
    BOOST_TEST(packs.err.find("holds a.xyz, which this command did not write") != std::string::npos,
               packs.err);
    BOOST_TEST(fs::exists(scratch() / "packs" / "a.xyz"));

    // A failing report leaves nothing behind.
    write("bad.xyz", "1\n" + kHeader + "1 0 nan 0 0.05 0\n");
    BOOST_TEST(run("report --a a.xyz --b b.xyz bad.xyz --out r").status == 1);
    BOOST_TEST(!fs::exists(scratch() / "r"));
    const Result ok = run("report --a a.xyz --b b.xyz c.xyz --label-a SGMP --label-b DEM --out r");
    BOOST_TEST(ok.status == 0, ok.err);
    const std::string report_command =
        "report --a a.xyz --b b.xyz c.xyz --label-a SGMP --label-b DEM --out r --force";
    BOOST_TEST(run(report_command).status == 0);
    const std::vector<std::string> files{"report.md", "report.csv", "report.json", "index.html"};
    std::vector<std::string> contents;
    for (const auto& file : files) {
        BOOST_TEST(fs::exists(scratch() / "r" / file), file);
        contents.push_back(sgmp::testing::read_bytes(scratch() / "r" / file));
    }
    // The same command gives the same bytes.
    BOOST_TEST(run(report_command).status == 0);
    for (std::size_t i = 0; i < files.size(); ++i) {
        BOOST_TEST(sgmp::testing::read_bytes(scratch() / "r" / files[i]) == contents[i], files[i]);
    }
}

BOOST_AUTO_TEST_CASE(crossval_and_regress_end_to_end) {
    for (int seed = 1; seed <= 4; ++seed) {
        good_pack("x" + std::to_string(seed) + ".xyz", static_cast<std::uint64_t>(seed));
    }
    write("manifest.csv",
          "role,group,count,seed,seconds,path\n"
          "candidate,loose-random,300,1,0.01,x1.xyz\ncandidate,loose-random,300,2,0.01,x2.xyz\n"
          "reference,DEM mu=0.5,300,1,2.0,x3.xyz\nreference,DEM mu=0.5,300,2,2.0,x4.xyz\n");
    write("results.csv",
          "arrangement,count,runtime_s,packing_fraction,table\nloose-random,300,551,0.5918,8.1\n");
    const Result ok = run("crossval --manifest manifest.csv --thesis results.csv --out cv");
    BOOST_TEST_REQUIRE(ok.status == 0, ok.err);
    for (const char* file : {"report.md", "index.html", "headline.csv", "crossval.json",
                             "baseline.json", "report.json"}) {
        BOOST_TEST(fs::exists(scratch() / "cv" / file), file);
    }
    const std::string md = sgmp::testing::read_bytes(scratch() / "cv" / "report.md");
    BOOST_TEST(md.find("## Which SGMP mode stands in for which DEM class") <
               md.find("## Verdict matrix"));
    BOOST_TEST(md.find("## Verdict matrix") < md.find("## Every comparison"));
    BOOST_TEST(md.find("| 300 | loose-random |") != std::string::npos);
    BOOST_TEST(md.find("551 (8.1)") != std::string::npos);

    // A run compared with itself passes; a baseline whose phi moved fails with status 3.
    BOOST_TEST(run("regress --baseline cv/baseline.json --current cv/baseline.json").status == 0);
    std::string moved = sgmp::testing::read_bytes(scratch() / "cv" / "baseline.json");
    const auto at = moved.find("\"value\": ");
    BOOST_TEST_REQUIRE(at != std::string::npos);
    moved.insert(at + 9, "1");  // the first value (phi, about 0.6) becomes about 10.6
    write("moved.json", moved);
    BOOST_TEST(run("regress --baseline moved.json --current cv/baseline.json").status == 3);
    // A baseline measured another way (g(r) bins of 0.5·d) is refused, not passed.
    std::string rebinned = sgmp::testing::read_bytes(scratch() / "cv" / "baseline.json");
    const auto bins = rebinned.find("\"gr_bin_width_over_d\": 0.02");
    BOOST_TEST_REQUIRE(bins != std::string::npos);
    rebinned.replace(bins, 27, "\"gr_bin_width_over_d\": 0.5");
    write("rebinned.json", rebinned);
    const Result unlike = run("regress --baseline rebinned.json --current cv/baseline.json");
    BOOST_TEST(unlike.status == 1);
    BOOST_TEST(unlike.err ==
               "sgmp-compare: cv/baseline.json: measured with gr_bin_width_over_d "
               "0.02, the baseline rebinned.json with 0.5; regress compares "
               "metrics measured alike\n");

    // Bad manifests: one line naming file:line, status 1, no report directory.
    write("bad.csv", "role,group,count,seed,seconds,path\ncandidate,a,three,1,,x1.xyz\n");
    const Result bad = run("crossval --manifest bad.csv --out cv-bad");
    BOOST_TEST(bad.status == 1);
    BOOST_TEST(bad.err == "sgmp-compare: bad.csv:2: count 'three' must be a positive integer\n");
    BOOST_TEST(!fs::exists(scratch() / "cv-bad"));
    write("one-side.csv", "role,group,count,seed,seconds,path\ncandidate,a,300,1,,x1.xyz\n");
    BOOST_TEST(run("crossval --manifest one-side.csv --out cv-bad").status == 1);
    BOOST_TEST(!fs::exists(scratch() / "cv-bad"));
}

// Reliability finding 8: one pack by two spellings, a link or a byte-identical copy counted
// as two seeds (sd 0, a "differ" verdict, status 0). Refused in one line naming both rows.
BOOST_AUTO_TEST_CASE(one_pack_spelled_two_ways_is_refused) {
    for (int seed = 1; seed <= 3; ++seed) {
        good_pack("d" + std::to_string(seed) + ".xyz", static_cast<std::uint64_t>(seed));
    }
    fs::remove(scratch() / "d1-link.xyz");
    fs::create_symlink("d1.xyz", scratch() / "d1-link.xyz");
    fs::copy_file(scratch() / "d1.xyz", scratch() / "d1-copy.xyz",
                  fs::copy_options::overwrite_existing);
    const std::string head = "role,group,count,seed,seconds,path\n";
    const std::string refs = "reference,DEM,300,1,,d2.xyz\nreference,DEM,300,2,,d3.xyz\n";
    const std::vector<std::pair<std::string, std::string>> cases{
        {"./d1.xyz",
         "sgmp-compare: same.csv:3: rows 2 and 3 name one pack ('d1.xyz' and "
         "'./d1.xyz', the same file): each pack counts once\n"},
        {"d1-link.xyz",
         "sgmp-compare: same.csv:3: rows 2 and 3 name one pack ('d1.xyz' and "
         "'d1-link.xyz', the same file): each pack counts once\n"},
        {"d1-copy.xyz",
         "sgmp-compare: same.csv:3: rows 2 and 3 name one pack ('d1.xyz' and "
         "'d1-copy.xyz', byte-identical copies): each pack counts once\n"}};
    for (const auto& [second, message] : cases) {
        write("same.csv",
              head + "candidate,A,300,1,,d1.xyz\ncandidate,A,300,2,," + second + "\n" + refs);
        const Result r = run("crossval --manifest same.csv --no-pictures --out cv-same");
        BOOST_TEST(r.status == 1, second);
        BOOST_TEST(r.err == message);
        BOOST_TEST(!fs::exists(scratch() / "cv-same"));
    }
    // report: the spellings were caught, a copy was not.
    const Result copy = run("report --a d1.xyz d1-copy.xyz --b d2.xyz d3.xyz --out r-same");
    BOOST_TEST(copy.status == 2);
    BOOST_TEST(copy.err ==
               "sgmp-compare: packs 'd1.xyz' and 'd1-copy.xyz' are byte-identical "
               "copies of one pack: each pack counts once\n");
    BOOST_TEST(!fs::exists(scratch() / "r-same"));
}

// Reliability finding 10: values of *.metrics.json were taken unchecked (a diameter of 0,
// -0.39 or 1e300, phi(y) 7.5 or NaN, a count of 61 for a pack of 60: that pack left its
// group). Each is refused in one line naming the file, the key and the rule.
BOOST_AUTO_TEST_CASE(metrics_json_values_keep_their_physical_range) {
    for (int seed = 1; seed <= 3; ++seed) {
        good_pack("v" + std::to_string(seed) + ".xyz", static_cast<std::uint64_t>(seed));
    }
    const Result measured = run("measure v1.xyz v2.xyz v3.xyz --no-voronoi --out vm --force");
    BOOST_TEST_REQUIRE(measured.status == 0, measured.err);
    const std::string json = sgmp::testing::read_bytes(scratch() / "vm" / "v1.metrics.json");
    const std::string phi_y = sgmp::testing::read_bytes(scratch() / "vm" / "v1.phi_y.csv");
    const std::string g_r = sgmp::testing::read_bytes(scratch() / "vm" / "v1.g_r.csv");
    const auto replaced = [](std::string text, const std::string& from, const std::string& to) {
        const auto at = text.find(from);
        BOOST_TEST_REQUIRE(at != std::string::npos, from);
        return text.replace(at, from.size(), to);
    };
    const auto value_of = [&](const std::string& key) {
        const auto at = json.find("\"" + key + "\": ") + key.size() + 4;
        return "\"" + key + "\": " + json.substr(at, json.find_first_of(",\n", at) - at);
    };
    const auto last_phi = phi_y.substr(phi_y.rfind(',') + 1);  // "0.5…\n"
    const std::vector<std::tuple<std::string, std::string, std::string>> bad{
        {replaced(json, value_of("diameter"), "\"diameter\": 0"), phi_y,
         "'diameter' is 0: the mean diameter must be finite and > 0"},
        {replaced(json, value_of("diameter"), "\"diameter\": -0.39"), phi_y,
         "'diameter' is -0.39: the mean diameter must be finite and > 0"},
        {replaced(json, value_of("diameter"), "\"diameter\": 1e300"), phi_y,
         "'diameter' is 1e+300: half the mean diameter must lie between radius_min and "
         "radius_max"},
        {json, replaced(phi_y, last_phi, "7.5\n"), "phi(y) = 7.5 is physically impossible"},
        {json, replaced(phi_y, last_phi, "nan\n"), "phi(y) = nan is physically impossible"},
        {replaced(json, "\"count\": 300", "\"count\": 301"), phi_y,
         "'count' is 301: g_r_detail.space_density times the volume of its space holds 300 "
         "spheres"},
    };
    for (const auto& [text, slabs, message] : bad) {
        write("vm/bad.metrics.json", text);
        write("vm/bad.phi_y.csv", slabs);
        write("vm/bad.g_r.csv", g_r);
        const Result r =
            run("report --a vm/bad.metrics.json vm/v2.metrics.json --b vm/v3.metrics.json "
                "--no-voronoi --out r-bad");
        BOOST_TEST(r.status == 1, message << ": " << r.err);
        BOOST_TEST(lines(r.err) == 1u, r.err);
        BOOST_TEST(r.err.find("sgmp-compare: vm/bad.metrics.json: ") == 0u, r.err);
        BOOST_TEST(r.err.find(message) != std::string::npos, r.err);
        BOOST_TEST(!fs::exists(scratch() / "r-bad"));
    }
    // The files as measured pass.
    const Result good = run(
        "report --a vm/v1.metrics.json vm/v2.metrics.json --b vm/v3.metrics.json vm/v1.metrics.json"
        " --no-voronoi --out r-good --force");
    BOOST_TEST(good.status == 2);  // v1 twice: one pack
    const Result fine =
        run("report --a vm/v1.metrics.json vm/v2.metrics.json --b vm/v3.metrics.json "
            "--no-voronoi --out r-good --force");
    BOOST_TEST(fine.status == 0, fine.err);
}

// Reliability finding 14: nlohmann's own messages escaped, naming no file (a number
// beyond a double in a baseline), or after a whole run (a Latin-1 byte in a header value
// or a group name broke the JSON writer). Each is one line naming the file; the Latin-1
// byte is refused as the input is read.
BOOST_AUTO_TEST_CASE(json_failures_name_the_file_and_latin1_is_refused_at_input) {
    write("overflow.json", "{\"entries\": [{\"value\": 0.01e30802}]}\n");
    const Result big = run("regress --baseline overflow.json --current overflow.json");
    BOOST_TEST(big.status == 1);
    BOOST_TEST(big.err ==
               "sgmp-compare: overflow.json: not valid JSON (numbers must fit a "
               "double): number overflow parsing '0.01e30802'\n");
    write("latin1.xyz",
          "1\nProperties=id:I:1:pos:R:3:radius:R:1:color:I:1 note=caf\xe9\n"
          "1 0 0 0 0.05 0\n");
    const Result header = run("measure latin1.xyz --out latin1-out");
    BOOST_TEST(header.status == 1);
    BOOST_TEST(lines(header.err) == 1u, header.err);
    BOOST_TEST(header.err.find("latin1.xyz:2: header entry 'note=caf\\xe9' is not UTF-8") !=
                   std::string::npos,
               header.err);
    BOOST_TEST(!fs::exists(scratch() / "latin1-out"));
    for (int seed = 1; seed <= 2; ++seed) {
        good_pack("u" + std::to_string(seed) + ".xyz", static_cast<std::uint64_t>(seed));
    }
    write("latin1.csv",
          "role,group,count,seed,seconds,path\ncandidate,caf\xe9,300,1,,u1.xyz\n"
          "reference,DEM,300,1,,u2.xyz\n");
    const Result group = run("crossval --manifest latin1.csv --no-pictures --out latin1-cv");
    BOOST_TEST(group.status == 1);
    BOOST_TEST(group.err ==
               "sgmp-compare: latin1.csv:2: field 'caf\\xe9' is not UTF-8 (a "
               "Latin-1 byte?): a manifest must be UTF-8 text\n");
    BOOST_TEST(!fs::exists(scratch() / "latin1-cv"));
    good_pack("caf\xe9.xyz", 1);  // a file name reaches provenance.input
    const Result name = run("measure 'caf\xe9.xyz' --no-voronoi --out latin1-name");
    BOOST_TEST(name.status == 2);
    BOOST_TEST(name.err ==
               "sgmp-compare: pack 'caf\\xe9.xyz': a file name must be UTF-8 (a "
               "Latin-1 byte?)\n");
    BOOST_TEST(!fs::exists(scratch() / "latin1-name"));
}

// Reliability finding 17: group names reached report.md raw (`<script>`, `|`) and
// report.csv and headline.csv as spreadsheet formulas (`=HYPERLINK(…)`). They are refused
// at input in one line (the manifest's rule, sgmp-compare report's labels too).
BOOST_AUTO_TEST_CASE(group_names_that_could_act_in_a_report_are_refused) {
    for (int seed = 1; seed <= 2; ++seed) {
        good_pack("g" + std::to_string(seed) + ".xyz", static_cast<std::uint64_t>(seed));
    }
    for (const std::string group : {"=HYPERLINK(\"\"http://x\"\";\"\"y\"\")", "+1", "-1",
                                    "@SUM(A1)", "<script>x</script>", "a|b", "[x](javascript:y)"}) {
        write("names.csv", "role,group,count,seed,seconds,path\ncandidate,\"" + group +
                               "\",300,1,,g1.xyz\nreference,DEM,300,1,,g2.xyz\n");
        const Result r = run("crossval --manifest names.csv --no-pictures --out names-cv");
        BOOST_TEST(r.status == 1, group);
        BOOST_TEST(lines(r.err) == 1u, r.err);
        BOOST_TEST(r.err.find("sgmp-compare: names.csv:2: group '") == 0u, r.err);
        BOOST_TEST(r.err.find("may not start with '=', '+', '-', '@'") != std::string::npos, r.err);
        BOOST_TEST(!fs::exists(scratch() / "names-cv"));
    }
    const Result label = run("report --a g1.xyz --b g2.xyz --label-a '=1+1' --out names-r");
    BOOST_TEST(label.status == 2);
    BOOST_TEST(label.err.find("sgmp-compare: label '=1+1': a group name must be") == 0u, label.err);
}

// Reliability finding 11: the LAMMPS data reader keeps the extended XYZ reader's header
// rule; `header FILE KEY` printed an escape sequence from a comment raw.
BOOST_AUTO_TEST_CASE(header_of_a_data_file_never_prints_control_bytes) {
    write("escape.data",
          "LAMMPS data file\n# note=\x1b]0;owned\x07\n\n1 atoms\n1 atom types\n\n"
          "-1 1 xlo xhi\n-1 1 ylo yhi\n-1 1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.2 1 0 -0.9 0\n");
    const Result r = run("header escape.data note");
    BOOST_TEST(r.status == 1);
    BOOST_TEST(r.out.empty());
    BOOST_TEST(r.err ==
               "sgmp-compare: escape.data:2: header entry 'note=\\x1b]0;owned\\x07' "
               "holds a control character\n");
}

BOOST_AUTO_TEST_SUITE_END()
