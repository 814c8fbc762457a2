// The `sgmp` executable: errors, refusal to overwrite, determinism of the written bytes,
// config files, the arrange subcommand.
#include <sys/wait.h>

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/version.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

namespace {

using Run = sgmp::testing::CommandRun;

/// A fresh scratch directory per test case; `run` runs `sgmp ARGS` there.
struct Scratch : sgmp::testing::ProgramScratch {
    Scratch()
        : ProgramScratch(
              "engine-cli-" + boost::unit_test::framework::current_test_case().p_name.get(),
              SGMP_EXECUTABLE) {}
};

/// `sgmp pack ARGS` fails with `status`: one line starting "sgmp: EXPECTED", no pack.
void expect_failure(const Scratch& s, const std::string& args, const std::string& expected,
                    int status) {
    const Run r =
        s.run("pack --arrangement small-dense --seed 1 --out '" + s.path("p.xyz") + "' " + args);
    BOOST_TEST_INFO("args: " << args << "; stderr: " << r.err);
    BOOST_TEST(r.status == status);
    BOOST_TEST(r.err.find("sgmp: " + expected) == 0u);
    BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    BOOST_TEST(!fs::exists(s.path("p.xyz")));
}

/// A usage error: exit 2.
void expect_refused(const Scratch& s, const std::string& args, const std::string& expected) {
    expect_failure(s, args, expected, 2);
}

/// A bad input file: one line naming file:line and the rule, exit 1, no pack.
void expect_bad_file(const Scratch& s, const std::string& args, const std::string& expected) {
    expect_failure(s, args, expected, 1);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(cli)

BOOST_AUTO_TEST_CASE(bad_values_are_refused_with_option_value_and_rule) {
    const Scratch s;
    expect_refused(s, "--count 0", "--count 0: must be between 1 and 10000000");
    expect_refused(s, "--count 10000001", "--count 10000001: must be between");
    expect_refused(s, "--count 1", "--count 1: the diameter");
    expect_refused(s, "--count 100 --phi-target 0", "--phi-target 0: must be in (0, 0.74048]");
    expect_refused(s, "--count 100 --phi-target 0.75", "--phi-target 0.75: must be in");
    expect_refused(s, "--count 100 --circle-factor 1", "--circle-factor 1: must be");
    expect_refused(s, "--count 100 --sweep-positions 2", "--sweep-positions 2: every stage");
    expect_refused(s, "--count 100 --sweep-stages 8,4", "--sweep-stages 8,4: stages must");
    expect_refused(s, "--count 100 --fall-step 0", "--fall-step 0: must be greater than 0");
    // The diameter bound applies to the step fall alone: the exact fall does not use the step.
    expect_refused(s, "--count 100 --fall step --fall-step 0.5",
                   "--fall-step 0.5: must be greater than 0 "
                   "and less than the diameter");
    expect_refused(s, "--count 100 --fall bounce", "--fall bounce: must be one of exact, step");
    expect_refused(s, "--count 100 --gap small", "--gap small: must be one of largest, random");
    expect_refused(s, "--count 100 --size-modes 1:0.5,x", "--size-modes 1:0.5,x: must be");
    const Run r = s.run("pack --count 100 --arrangement spiral --out '" + s.path("p.xyz") + "'");
    BOOST_TEST(r.status == 2);
    BOOST_TEST(r.err ==
               "sgmp: --arrangement spiral: must be one of single-column, small-dense, "
               "large-dense, loose-random\n");
}

BOOST_AUTO_TEST_CASE(running_out_of_memory_is_one_line_and_no_file) {
    // Under a 200 MB address-space limit a 3·10⁶-sphere pack cannot be made: exit 1, one
    // line that names what was being built (it was "sgmp: std::bad_alloc").
    const Scratch s;
    const Run r =
        s.run("pack --count 3000000 --arrangement loose-random --out '" + s.path("p.xyz") + "'",
              "ulimit -v 200000;");
    BOOST_TEST(r.status == 1);
    BOOST_TEST(r.err.rfind("sgmp: building the pack of 3000000 spheres: out of memory: ", 0) == 0,
               r.err);
    BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    BOOST_TEST(!fs::exists(s.path("p.xyz")));
}

BOOST_AUTO_TEST_CASE(size_distribution_files_are_read_and_checked) {
    const Scratch s;
    const auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(s.path(name)) << text;
        return "--count 600 --size-distribution '" + s.path(name) + "' ";
    };
    // Mass fractions 51 : 17 (the rest binder): normalised, with one warning line.
    const std::string blend =
        write("blend.csv", "diameter,fraction,density\n10,0.51,1.95\n5,0.17,2.7\n");
    const Run ok = s.run("pack --arrangement loose-random --out '" + s.path("b.xyz") + "' " +
                         blend + "--fraction-basis mass");
    BOOST_TEST(ok.status == 0, ok.err);
    BOOST_TEST(ok.err.find("sgmp: warning: --size-distribution") == 0u);
    BOOST_TEST(ok.err.find("fractions sum to 0.68; normalised to 1\n") != std::string::npos);
    const Run modes = s.run("pack --arrangement loose-random --count 600 --out '" +
                            s.path("m.xyz") + "' --size-modes 1:0.3,0.5:0.3");
    BOOST_TEST(modes.status == 0, modes.err);
    BOOST_TEST(modes.err.find("sgmp: warning: --size-modes 1:0.3,0.5:0.3: fractions sum to 0.6; "
                              "normalised to 1\n") == 0u);
    const std::string pack = sgmp::testing::read_bytes(s.path("b.xyz"));
    BOOST_TEST(pack.find(":species_id:I:1:masses:R:1 ") != std::string::npos);  // densities stated
    BOOST_TEST(pack.find(" fraction_basis=mass ") != std::string::npos);
    BOOST_TEST(pack.find(" species_mass_fractions=") != std::string::npos);
    expect_bad_file(s, write("colour.csv", "diameter,fraction,colour\n1,1,2\n"),
                    "--size-distribution " + s.path("colour.csv") + ":1: unknown column 'colour'");
    expect_bad_file(s, write("neg.csv", "diameter,fraction\n1,-1\n1,2\n"),
                    "--size-distribution " + s.path("neg.csv") + ":2: fraction -1");
    expect_refused(s, "--count 100 --size-distribution '" + s.path("missing.csv") + "'",
                   "--size-distribution " + s.path("missing.csv") + ": must name a readable file");
    expect_refused(s, write("nod.csv", "diameter,fraction\n1,1\n0.5,1\n") + "--fraction-basis mass",
                   "--fraction-basis mass: needs a density for every species");
    expect_refused(s, blend + "--size-modes 1:1",
                   "--size-distribution " + s.path("blend.csv") +
                       ": give either --size-modes or --size-distribution, not both");
    expect_refused(s, "--count 100 --fraction-basis weight",
                   "--fraction-basis weight: must be one of number, volume, mass");
}

BOOST_AUTO_TEST_CASE(lognormal_distributions_pack_into_equal_classes) {
    // Five classes of equal volume fraction from a lognormal volume distribution: 500
    // spheres split by volume, the text recorded as the distribution's provenance.
    const Scratch s;
    const Run ok = s.run("pack --arrangement loose-random --count 500 --out '" + s.path("l.xyz") +
                         "' --size-distribution lognormal:200:0.3:5 --fraction-basis volume");
    BOOST_TEST(ok.status == 0, ok.err);
    const std::string pack = sgmp::testing::read_bytes(s.path("l.xyz"));
    BOOST_TEST(pack.find(" size_distribution=lognormal:200:0.3:5 ") != std::string::npos);
    BOOST_TEST(pack.find(":species_id:I:1 ") != std::string::npos);  // no densities: no masses
    expect_refused(s, "--count 100 --size-distribution lognormal:200:-1",
                   "--size-distribution lognormal:200:-1: SIGMA must lie in (0, 3]");
    expect_refused(s, "--count 100 --size-distribution lognormal:200:0.3:0",
                   "--size-distribution lognormal:200:0.3:0: CLASSES must be a whole number "
                   "from 1 to 1000");
    expect_refused(s, "--count 100 --size-distribution lognormal:200:0.3:5:0.5:0.2",
                   "--size-distribution lognormal:200:0.3:5:0.5:0.2: the quantiles must satisfy "
                   "0 < QLO < QHI < 1");
    expect_refused(s, "--count 100 --size-distribution lognormal:200",
                   "--size-distribution lognormal:200: must be "
                   "lognormal:MEDIAN:SIGMA[:CLASSES[:QLO:QHI]], e.g. "
                   "lognormal:200:0.4:10:0.01:0.99");
}

BOOST_AUTO_TEST_CASE(bad_relaxation_values_are_refused_with_option_value_and_rule) {
    const Scratch s;
    expect_refused(s, "--count 100 --relax soft",
                   "--relax soft: must be one of none, frictionless, frictional");
    expect_refused(s, "--count 100 --relax frictionless --relax-stiffness 1",
                   "--relax-stiffness 1: must be in [100, 1e12]");
    expect_refused(s, "--count 100 --relax frictionless --relax-stages 11",
                   "--relax-stages 11: must be 1 to 10");
    expect_refused(s, "--count 100 --relax frictionless --relax-shell 0.5",
                   "--relax-shell 0.5: must be in [0, 0.01]");
    expect_refused(s, "--count 100 --relax frictionless --relax-time 0",
                   "--relax-time 0: must be in (0, 10000]");
    expect_refused(s, "--count 100 --relax frictionless --relax-crossings -1",
                   "--relax-crossings -1: must be in (0, 10000]");
    expect_refused(s, "--count 100 --relax frictional --relax-friction -1",
                   "--relax-friction -1: must be in [0, 10]");
    expect_refused(s, "--count 100 --relax frictional --relax-tangential-ratio 2",
                   "--relax-tangential-ratio 2: must be in (0, 1]");
}

BOOST_AUTO_TEST_CASE(relax_none_writes_the_bytes_of_no_relaxation_and_relaxed_packs_repeat) {
    const Scratch s;
    const std::string common = "pack --count 300 --arrangement loose-random --seed 3 --out ";
    BOOST_TEST(s.run(common + "'" + s.path("plain.xyz") + "'").status == 0);
    BOOST_TEST(s.run(common + "'" + s.path("none.xyz") + "' --relax none").status == 0);
    BOOST_TEST(sgmp::testing::read_bytes(s.path("plain.xyz")) ==
               sgmp::testing::read_bytes(s.path("none.xyz")));
    // A settling stopped by --relax-settle-limit before it balances every sphere is not
    // certified: refused without --keep-uncertified (one line naming the worst sphere and
    // its residual), no file; with it, written with certified=false.
    const std::string stopped = " --relax frictionless --relax-settle-limit 1";
    const Run refused = s.run(common + "'" + s.path("r.xyz") + "'" + stopped);
    BOOST_TEST(refused.status == 1);
    BOOST_TEST(refused.err.find("not a certified frictionless equilibrium") != std::string::npos,
               refused.err);
    BOOST_TEST(refused.err.find("m*g") != std::string::npos, refused.err);
    BOOST_TEST(!std::filesystem::exists(s.path("r.xyz")));
    const Run kept = s.run(common + "'" + s.path("k.xyz") + "'" + stopped + " --keep-uncertified");
    BOOST_TEST(kept.status == 0, kept.err);
    const auto kept_pack = sgmp::read_pack_file(s.path("k.xyz"));
    BOOST_TEST(kept_pack.metadata.get("certified").value_or("") == "false");
    BOOST_TEST(kept_pack.metadata.get("relax_settle_end").value_or("") == "limit");
    // The frictionless one ends in a certified equilibrium (settle_test.cpp).
    const Run a = s.run(common + "'" + s.path("a.xyz") + "' --relax frictionless");
    const Run b = s.run(common + "'" + s.path("b.xyz") + "' --relax frictionless");
    BOOST_TEST(a.status == 0);
    BOOST_TEST(b.status == 0);
    BOOST_TEST(sgmp::testing::read_bytes(s.path("a.xyz")) ==
               sgmp::testing::read_bytes(s.path("b.xyz")));
    BOOST_TEST(sgmp::testing::read_bytes(s.path("a.xyz")) !=
               sgmp::testing::read_bytes(s.path("plain.xyz")));
    BOOST_TEST(a.out.find("overlaps=0") != std::string::npos);
    const auto pack = sgmp::read_pack_file(s.path("a.xyz"));
    BOOST_TEST(pack.metadata.get("relax").value_or("") == "frictionless");
    BOOST_TEST(pack.metadata.get("certified").value_or("") == "true");
    BOOST_TEST(!sgmp::read_pack_file(s.path("plain.xyz")).metadata.contains("relax"));
    // As a DEM start (a LAMMPS data file), the deposited pack gets one warning line; the
    // relaxed one and other formats none.
    const std::string warning = "sgmp convert: warning: this SGMP pack was not relaxed";
    const Run plain_data =
        s.run("convert '" + s.path("plain.xyz") + "' '" + s.path("plain.data") + "'");
    BOOST_TEST(plain_data.status == 0, plain_data.err);
    BOOST_TEST(plain_data.err.rfind(warning, 0) == 0u, plain_data.err);
    BOOST_TEST(std::count(plain_data.err.begin(), plain_data.err.end(), '\n') == 1);
    const Run relaxed_data = s.run("convert '" + s.path("a.xyz") + "' '" + s.path("a.data") + "'");
    BOOST_TEST(relaxed_data.err.find(warning) == std::string::npos, relaxed_data.err);
    const Run plain_dump =
        s.run("convert '" + s.path("plain.xyz") + "' '" + s.path("plain.dump") + "'");
    BOOST_TEST(plain_dump.err.find(warning) == std::string::npos, plain_dump.err);
    // --origin zero: the container's corner at 0, so Origin is 0 and centres move by 0.625.
    const Run zero =
        s.run("convert '" + s.path("plain.xyz") + "' '" + s.path("zero.xyz") + "' --origin zero");
    BOOST_TEST(zero.status == 0, zero.err);
    const std::string moved = sgmp::testing::read_bytes(s.path("zero.xyz"));
    BOOST_TEST(moved.find(" Origin=\"0 0 0\" ") != std::string::npos);
    BOOST_TEST(moved.find(" origin_shift=\"0.625 0.625 0.625\"") != std::string::npos);
    const auto a0 = sgmp::read_pack_file(s.path("plain.xyz")).particles.at(0).center;
    const auto b0 = sgmp::read_pack_file(s.path("zero.xyz")).particles.at(0).center;
    BOOST_TEST((b0 - a0 - sgmp::Vec3::Constant(0.625)).norm() <= 1e-15);
    const Run bad =
        s.run("convert '" + s.path("plain.xyz") + "' '" + s.path("o.xyz") + "' --origin corner");
    BOOST_TEST(bad.status == 2);
    BOOST_TEST(bad.err.find("--origin") != std::string::npos, bad.err);
    BOOST_TEST(std::count(bad.err.begin(), bad.err.end(), '\n') == 1);
    BOOST_TEST(!fs::exists(s.path("o.xyz")));
}

BOOST_AUTO_TEST_CASE(convert_says_clumped_spheres_overlap_instead_of_listing_their_pairs) {
    // The text-precision check listed every overlapping pair: 200,000 spheres at one point
    // took 103 s (O(N²) pairs). Past the crowding limit (crowding.hpp) convert says so in
    // one warning line, converts, and lists nothing; 20,000 here (2·10⁸ pairs before).
    const Scratch s;
    {
        std::ofstream clump(s.path("clump.xyz"));
        clump << "20000\nProperties=species:S:1:pos:R:3:radius:R:1\n";
        for (int i = 0; i < 20000; ++i) {
            clump << "H 0.00000001 0 0 0.01\n";
        }
    }
    const Run r = s.run("convert '" + s.path("clump.xyz") + "' '" + s.path("clump.dump") + "'");
    BOOST_TEST(r.status == 0, r.err);
    BOOST_TEST(r.err.rfind("sgmp convert: warning: 20000 sphere centres in one cube", 0) == 0u,
               r.err);
    BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    BOOST_TEST(sgmp::read_pack_file(s.path("clump.dump")).particles.size() == 20000u);
}

BOOST_AUTO_TEST_CASE(an_unwritable_output_is_refused_before_packing) {
    const Scratch s;
    std::ofstream(s.path("plain-file")) << "x";
    const Run r = s.run("pack --count 100 --arrangement small-dense --out '" +
                        s.path("plain-file") + "/p.xyz'");
    BOOST_TEST(r.status == 2);
    BOOST_TEST(r.err.find(s.path("plain-file")) != std::string::npos);
    BOOST_TEST(r.out.empty());  // refused before any packing summary
}

BOOST_AUTO_TEST_CASE(an_existing_output_is_kept_unless_forced) {
    const Scratch s;
    std::ofstream(s.path("p.xyz")) << "keep me";
    const std::string args =
        "pack --count 100 --arrangement large-dense --out '" + s.path("p.xyz") + "'";
    const Run refused = s.run(args);
    BOOST_TEST(refused.status == 2);
    BOOST_TEST(sgmp::testing::read_bytes(s.path("p.xyz")) == "keep me");
    const Run forced = s.run(args + " --force");
    BOOST_TEST(forced.status == 0);
    BOOST_TEST(sgmp::read_pack_file(s.path("p.xyz")).particles.size() == 100u);
}

BOOST_AUTO_TEST_CASE(same_arguments_write_the_same_bytes_and_a_summary_line) {
    const Scratch s;
    const std::string common =
        "pack --count 400 --arrangement loose-random --seed 5 --gap "
        "random --out ";
    const Run a = s.run(common + "'" + s.path("a.xyz") + "'");
    const Run b = s.run(common + "'" + s.path("b.xyz") + "'");
    BOOST_TEST(a.status == 0);
    BOOST_TEST(b.status == 0);
    BOOST_TEST(sgmp::testing::read_bytes(s.path("a.xyz")) ==
               sgmp::testing::read_bytes(s.path("b.xyz")));
    BOOST_TEST(sgmp::testing::read_bytes(s.path("a.xyz")).size() > 1000u);
    BOOST_TEST(a.out.find("sgmp: packed 400 particles, loose-random, d=") == 0u);
    BOOST_TEST(a.out.find("phi(control volume)=0.") != std::string::npos);
    BOOST_TEST(a.out.find("overlaps=0") != std::string::npos);
    BOOST_TEST(a.err.empty());  // no progress line when stderr is not a terminal
    const auto pack = sgmp::read_pack_file(s.path("a.xyz"));
    BOOST_TEST(pack.metadata.get("generator").value_or("") == "sgmp");
    BOOST_TEST(pack.metadata.get("seed").value_or("") == "5");
    BOOST_TEST(pack.metadata.get("gap").value_or("") == "random");
}

BOOST_AUTO_TEST_CASE(a_config_file_repeats_a_run_and_the_command_line_wins) {
    const Scratch s;
    std::ofstream(s.path("run.toml")) << "count = 200\narrangement = \"single-column\"\n"
                                         "seed = 3\nfall = \"step\"\nout = \""
                                      << s.path("c.xyz") << "\"\n";
    const Run a = s.run("pack --config '" + s.path("run.toml") + "'");
    BOOST_TEST(a.status == 0);
    const auto pack = sgmp::read_pack_file(s.path("c.xyz"));
    BOOST_TEST(pack.particles.size() == 200u);
    BOOST_TEST(pack.metadata.get("fall").value_or("") == "step");
    const Run b = s.run("pack --config '" + s.path("run.toml") + "' --count 150 --out '" +
                        s.path("d.xyz") + "'");
    BOOST_TEST(b.status == 0);
    BOOST_TEST(sgmp::read_pack_file(s.path("d.xyz")).particles.size() == 150u);
    // Keys as pack headers write them (snake_case) are accepted too.
    std::ofstream(s.path("header.toml")) << "count = 120\narrangement = \"large-dense\"\n"
                                            "phi_target = 0.6\nfall_step = 0.002\n"
                                            "sweep_stages = \"8,120\"\n";
    const Run c =
        s.run("pack --config '" + s.path("header.toml") + "' --out '" + s.path("e.xyz") + "'");
    BOOST_TEST(c.status == 0);
    const auto e = sgmp::read_pack_file(s.path("e.xyz"));
    BOOST_TEST(e.metadata.get("phi_target").value_or("") == "0.6");
    BOOST_TEST(e.metadata.get("fall_step").value_or("") == "0.002");
    BOOST_TEST(e.metadata.get("sweep_stages").value_or("") == "8,120");
    // A key naming no option: one line naming the file and the key, nothing written.
    std::ofstream(s.path("bogus.toml")) << "count = 120\nbogus_key = 3\n";
    const Run bogus =
        s.run("pack --config '" + s.path("bogus.toml") + "' --out '" + s.path("x.xyz") + "'");
    BOOST_TEST(bogus.status == 2);
    BOOST_TEST(bogus.err == "sgmp: --config " + s.path("bogus.toml") +
                                ": key 'bogus_key' names no option of 'pack' (--bogus-key)\n");
    BOOST_TEST(!fs::exists(s.path("x.xyz")));
    // A config file never grants --force: replacing a file is the typist's decision.
    std::ofstream(s.path("victim.txt")) << "precious";
    std::ofstream(s.path("force.toml"))
        << "count = 120\nforce = true\nout = \"" << s.path("victim.txt") << "\"\n";
    const Run forced = s.run("pack --config '" + s.path("force.toml") + "'");
    BOOST_TEST(forced.status == 2);
    BOOST_TEST(forced.err == "sgmp: --config " + s.path("force.toml") +
                                 ": key 'force' is taken only from the command line (--force)\n");
    BOOST_TEST(sgmp::testing::read_bytes(s.path("victim.txt")) == "precious");
    // A blend's header records its distribution file and the modes read from it; a
    // config copied from it repeats the pack (the modes are the file's record).
    std::ofstream(s.path("blend.csv")) << "diameter,fraction\n1,0.5\n0.5,0.5\n";
    const Run f =
        s.run("pack --count 300 --arrangement loose-random --seed 2 --out '" + s.path("f.xyz") +
              "' --size-distribution '" + s.path("blend.csv") + "' --fraction-basis volume");
    BOOST_TEST_REQUIRE(f.status == 0, f.err);
    const auto first = sgmp::read_pack_file(s.path("f.xyz"));
    std::ofstream(s.path("blend.toml"))
        << "count = 300\narrangement = \"loose-random\"\nseed = 2\nsize_modes = \""
        << first.metadata.get("size_modes").value_or("") << "\"\nsize_distribution = \""
        << s.path("blend.csv") << "\"\nfraction_basis = \"volume\"\n";
    const Run g =
        s.run("pack --config '" + s.path("blend.toml") + "' --out '" + s.path("g.xyz") + "'");
    BOOST_TEST_REQUIRE(g.status == 0, g.err);
    // Sizes typed on the command line in the other form replace the file's.
    const Run h = s.run("pack --config '" + s.path("blend.toml") + "' --size-modes 1:1 --out '" +
                        s.path("h.xyz") + "'");
    BOOST_TEST(h.status == 0, h.err);
    const auto again = sgmp::read_pack_file(s.path("g.xyz"));
    BOOST_TEST_REQUIRE(again.particles.size() == first.particles.size());
    for (std::size_t i = 0; i < first.particles.size(); ++i) {
        BOOST_TEST(again.particles[i].center.x() == first.particles[i].center.x());
        BOOST_TEST(again.particles[i].radius == first.particles[i].radius);
    }
}

BOOST_AUTO_TEST_CASE(arrange_writes_the_starting_positions) {
    const Scratch s;
    const Run r = s.run("arrange --count 300 --arrangement large-dense --seed 2 --out '" +
                        s.path("start.xyz") + "'");
    BOOST_TEST(r.status == 0);
    BOOST_TEST(r.out.find("start height") != std::string::npos);
    const auto pack = sgmp::read_pack_file(s.path("start.xyz"));
    BOOST_TEST(pack.particles.size() == 300u);
    BOOST_TEST(pack.metadata.get("stage").value_or("") == "start");
    BOOST_TEST(pack.particles.front().id == 1);
    BOOST_TEST(pack.particles.back().id == 300);
}

BOOST_AUTO_TEST_CASE(values_once_accepted_silently_are_refused) {
    const Scratch s;
    const std::string seed_rule = "must be a whole number from 0 to 18446744073709551615";
    expect_refused(s, "--count 100 --seed -1", "--seed -1: " + seed_rule);
    expect_refused(s, "--count 100 --seed 18446744073709551616",
                   "--seed 18446744073709551616: " + seed_rule);
    expect_refused(s, "--count 100 --sweep-stages ''",
                   "--sweep-stages \"\": must be comma-separated whole numbers");
    expect_refused(s, "--count 100 --phi-target 1e-300",
                   "--phi-target 1e-300: must be at least 0.001");
    expect_refused(s, "--config '" + s.dir.string() + "'",
                   "--config " + s.dir.string() + ": must name a readable file");
}

BOOST_AUTO_TEST_CASE(a_full_disk_exits_1_not_the_usage_code) {
    const Scratch s;
    // SIGXFSZ ignored, so the write fails with EFBIG as it would with ENOSPC.
    const std::string command = "bash -c 'trap \"\" XFSZ; ulimit -f 64; exec \"$0\" \"$@\"' '" +
                                std::string(SGMP_EXECUTABLE) +
                                "' pack --count 20000 --arrangement small-dense --seed 1 --out '" +
                                s.path("p.xyz.gz") + "' 2>'" + s.path("stderr") + "'";
    const int raw = std::system(command.c_str());
    BOOST_TEST(WIFEXITED(raw));
    BOOST_TEST(WEXITSTATUS(raw) == 1);
    // The error is the last line (a slow machine may print a progress line before it).
    const std::string err = sgmp::testing::read_bytes(s.path("stderr"));
    const std::string expected = "sgmp: " + s.path("p.xyz.gz") + ": write failed: File too large\n";
    BOOST_TEST((err.size() >= expected.size() &&
                err.compare(err.size() - expected.size(), expected.size(), expected) == 0 &&
                (err.size() == expected.size() || err[err.size() - expected.size() - 1] == '\n')));
    BOOST_TEST(!fs::exists(s.path("p.xyz.gz")));
    BOOST_TEST(std::distance(fs::directory_iterator(s.dir), fs::directory_iterator()) == 1);
}

BOOST_AUTO_TEST_CASE(sigint_exits_130_with_one_line_and_no_file) {
    const Scratch s;
    // SIGINT half a second into a pack that takes several seconds.
    const std::string command = "'" + std::string(SGMP_EXECUTABLE) +
                                "' pack --count 100000 --arrangement loose-random --seed 1 "
                                "--out '" +
                                s.path("p.xyz.gz") + "' 2>'" + s.path("stderr") +
                                "' & pid=$!; sleep 0.5; kill -INT $pid; wait $pid; echo $? >'" +
                                s.path("status") + "'";
    BOOST_TEST(std::system(command.c_str()) == 0);
    BOOST_TEST(sgmp::testing::read_bytes(s.path("status")) == "130\n");
    BOOST_TEST(sgmp::testing::read_bytes(s.path("stderr")) ==
               "sgmp: interrupted by SIGINT; its temporary files are removed\n");
    BOOST_TEST(std::distance(fs::directory_iterator(s.dir), fs::directory_iterator()) == 2);
}

BOOST_AUTO_TEST_CASE(help_and_version) {
    const Scratch s;
    const Run help = s.run("pack --help");
    BOOST_TEST(help.status == 0);
    for (const char* option :
         {"--count",        "--arrangement",      "--seed",          "--out",
          "--force",        "--phi-target",       "--circle-factor", "--sweep-positions",
          "--sweep-stages", "--lower-neighbours", "--gap",           "--fall",
          "--fall-step",    "--contact",          "--momentum",      "--walls",
          "--stall-moves",  "--max-moves",        "--config",        "--size-modes"}) {
        BOOST_TEST_INFO(option);
        BOOST_TEST(help.out.find(option) != std::string::npos);
    }
    BOOST_TEST(help.out.find("=0.001") != std::string::npos);  // defaults are shown
    // Every program's and command's help fits 100 columns (lines once ran to 250): the
    // descriptions wrap under their column. UTF-8 signs count once per byte here.
    const fs::path bin = fs::path(SGMP_EXECUTABLE).parent_path().parent_path();
    for (const auto& [program, command] :
         std::vector<std::pair<std::string, std::string>>{{"sgmp/sgmp", ""},
                                                          {"sgmp/sgmp", "pack"},
                                                          {"sgmp/sgmp", "arrange"},
                                                          {"sgmp/sgmp", "batch"},
                                                          {"sgmp/sgmp", "convert"},
                                                          {"sgmp/sgmp", "render"},
                                                          {"compare/sgmp-compare", ""},
                                                          {"compare/sgmp-compare", "measure"},
                                                          {"compare/sgmp-compare", "report"},
                                                          {"compare/sgmp-compare", "crossval"},
                                                          {"compare/sgmp-compare", "regress"},
                                                          {"reference/sgmp-reference", "pour"},
                                                          {"reference/sgmp-reference", "settle"}}) {
        const auto run = sgmp::testing::run_command(
            "'" + (bin / program).string() + "' " + command + " --help", s.dir);
        BOOST_TEST_INFO(program << " " << command);
        BOOST_TEST(run.status == 0);
        std::istringstream lines(run.out);
        std::size_t widest = 0;
        for (std::string line; std::getline(lines, line);) {
            widest = std::max(widest, line.size());
        }
        BOOST_TEST(widest <= 100u);
    }
    const Run version = s.run("--version");
    BOOST_TEST(version.status == 0);
    // The bare version, the same text pack headers record as `version`.
    BOOST_TEST(version.out == std::string(sgmp::version()) + "\n");
}

BOOST_AUTO_TEST_SUITE_END()
