// The command line: bad input gives one line on stderr and a non-zero status (2 for usage),
// and never leaves a half-written output directory.

#include <boost/test/unit_test.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

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

BOOST_AUTO_TEST_SUITE_END()
