// sgmp-compare crossval's group-sequential options: --max-seeds bounds (exit 2, one line),
// the looks and limiting side in report.csv, and seeds-needed.csv.
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "sgmp/pack/pack_file.hpp"
#include "synthetic_packs.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kTool = fs::path(SGMP_BINARY_DIR) / "compare" / "sgmp-compare";

const fs::path& scratch() {
    static const sgmp::testing::TestDirectory dir("compare-sequential-cli");
    return dir.path();
}

sgmp::testing::CommandRun run(const std::string& arguments) {
    return sgmp::testing::run_command(
        "cd '" + scratch().string() + "' && '" + kTool.string() + "' " + arguments, scratch());
}

/// Three candidate and three reference packs of 300 (jittered lattices) and their manifest.
void write_manifest() {
    std::ofstream manifest(scratch() / "manifest.csv");
    manifest << "role,group,count,seed,seconds,path\n";
    for (int seed = 1; seed <= 6; ++seed) {
        const std::string name = "p" + std::to_string(seed) + ".xyz";
        sgmp::write_pack_file(
            scratch() / name,
            sgmp::testing::jittered_fcc_pack(300, 1.05, 0.02, std::uint64_t(seed)), true);
        manifest << (seed <= 3 ? "candidate,mode-a,300," : "reference,DEM mu=0.5,300,") << seed
                 << ",0.01," << name << '\n';
    }
}

std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sequential_cli)

BOOST_AUTO_TEST_CASE(max_seeds_outside_2_to_10000_is_a_usage_error) {
    write_manifest();
    for (const char* bad : {"1", "10001", "0", "-3"}) {
        const auto r = run(std::string("crossval --manifest manifest.csv --no-pictures --out bad "
                                       "--max-seeds ") +
                           bad);
        BOOST_TEST(r.status == 2, bad);
        BOOST_TEST(count_of(r.err, "\n") == 1u, r.err);
        BOOST_TEST(r.err.rfind("sgmp-compare: ", 0) == 0u, r.err);
        BOOST_TEST(r.err.find("--max-seeds") != std::string::npos, r.err);
        BOOST_TEST(!fs::exists(scratch() / "bad"));
    }
}

BOOST_AUTO_TEST_CASE(crossval_reports_looks_and_writes_seeds_needed) {
    write_manifest();
    const auto r =
        run("crossval --manifest manifest.csv --no-pictures --out cv --max-seeds 50 "
            "--first-look 3 --seeds-needed needed.csv");
    BOOST_TEST_REQUIRE(r.status == 0, r.err);
    const std::string csv = sgmp::testing::read_bytes(scratch() / "cv" / "report.csv");
    const std::string header = csv.substr(0, csv.find('\n'));
    BOOST_TEST(header.find(",seeds_to_decide,look,looks,alpha_spent,nominal_alpha,limited_by,"
                           "pours_to_decide") != std::string::npos);
    // φ is judged at look 1 of 11 (3, 8, …, 48, 50 seeds) against 3 pours: t = I(3)/I(50) =
    // 1.5/2.830 = 0.530, α(t) = 2(1 − Φ(1.95996/√0.530)) = 0.0070979 (group_sequential.hpp).
    const auto phi = csv.find("\n300,mode-a,DEM mu=0.5,phi,");
    BOOST_TEST_REQUIRE(phi != std::string::npos);
    const std::string row = csv.substr(phi + 1, csv.find('\n', phi + 1) - phi - 1);
    BOOST_TEST(row.find(",1,11,0.00709786,0.00709786,") != std::string::npos, row);
    // Identical lattices: every undecided row is open and needs the next look's 8 seeds.
    const std::string needed = sgmp::testing::read_bytes(scratch() / "needed.csv");
    BOOST_TEST(needed.rfind("mode,count,seeds_now,seeds_next,rows\n", 0) == 0u, needed);
    if (csv.find(",inconclusive,") != std::string::npos) {
        BOOST_TEST(needed.find("\nmode-a,300,3,8,") != std::string::npos, needed);
    }
    // Without --max-seeds: one look at the packs there are, the fixed-sample level 0.05.
    const auto once = run("crossval --manifest manifest.csv --no-pictures --out cv1");
    BOOST_TEST_REQUIRE(once.status == 0, once.err);
    const std::string csv1 = sgmp::testing::read_bytes(scratch() / "cv1" / "report.csv");
    BOOST_TEST(csv1.find(",1,1,0.05,0.05,") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
