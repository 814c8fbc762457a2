// Reliability findings 4, 5 and 14 at the command line of sgmp-compare: clumped spheres are
// refused in one line before any pair pass, whole files are read with a cap, and no
// message is longer than a short excerpt.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <string>

#include "sgmp/pack/pack_file.hpp"
#include "synthetic_packs.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

namespace {

using Run = sgmp::testing::CommandRun;

struct Scratch : sgmp::testing::ProgramScratch {
    Scratch()
        : ProgramScratch(
              "compare-memory-" + boost::unit_test::framework::current_test_case().p_name.get(),
              (fs::path(SGMP_BINARY_DIR) / "compare" / "sgmp-compare").string()) {}
};

const std::string kContainer = "--container '-0.625 0.625 -0.625 0.625 -0.625'";

std::size_t lines(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(cli)

// Finding 4: 8,000 spheres at one point took 38 s and 3.0 GB in measure and exited 0 (the
// pair passes were O(N²)). Now refused at once, in one line naming the first sphere.
BOOST_AUTO_TEST_CASE(measure_refuses_clumped_spheres_in_one_line) {
    const Scratch s;
    sgmp::Pack clump;
    for (int i = 0; i < 8000; ++i) {
        clump.particles.push_back(sgmp::testing::sphere(i + 1, 0.0, 0.0, 0.0, 0.01));
    }
    sgmp::write_pack_file(s.dir / "clump.xyz.gz", clump, false);
    const Run r = s.run("measure --no-voronoi " + kContainer + " --out '" + s.path("m") + "' '" +
                        s.path("clump.xyz.gz") + "'");
    BOOST_TEST_INFO("stderr: " << r.err);
    BOOST_TEST(r.status == 1);
    BOOST_TEST(lines(r.err) == 1u);
    BOOST_TEST(r.err.find("sgmp-compare: " + s.path("clump.xyz.gz") +
                          ": sphere id 1 at (0, 0, 0): 8000 sphere centres in one cube of side "
                          "2*r_min = 0.02 with it; at most 51 fit") == 0u);
    BOOST_TEST(!fs::exists(s.dir / "m"));
    // A valid pack of the same count is measured (the limit refuses nothing physical).
    sgmp::write_pack_file(s.dir / "good.xyz", sgmp::testing::jittered_fcc_pack(300, 1.05, 0.02, 1),
                          false);
    const Run good =
        s.run("measure --no-voronoi --out '" + s.path("g") + "' '" + s.path("good.xyz") + "'");
    BOOST_TEST_INFO("stderr: " << good.err);
    BOOST_TEST(good.status == 0);
}

// Finding 5: `crossval --metrics /dev/zero` and `report --a` with a *.metrics.json linked to
// /dev/zero ended in "std::bad_alloc". Now one line naming the file and the cap, exit 1.
// (SGMP_MAX_FILE_BYTES lowers the caps, so the devices are read only 1 MB far.)
BOOST_AUTO_TEST_CASE(whole_files_are_read_with_a_cap) {
    const Scratch s;
    const std::string cap = "SGMP_MAX_FILE_BYTES=1000000";
    sgmp::write_pack_file(s.dir / "a.xyz", sgmp::testing::jittered_fcc_pack(300, 1.05, 0.02, 1),
                          false);
    sgmp::write_pack_file(s.dir / "b.xyz", sgmp::testing::jittered_fcc_pack(300, 1.05, 0.02, 2),
                          false);
    fs::create_symlink("/dev/zero", s.dir / "z.metrics.json");
    const Run report =
        s.run("report --no-voronoi --a '" + s.path("z.metrics.json") + "' '" + s.path("a.xyz") +
                  "' --b '" + s.path("b.xyz") + "' --out '" + s.path("r") + "'",
              cap);
    BOOST_TEST_INFO("stderr: " << report.err);
    BOOST_TEST(report.status == 1);
    BOOST_TEST(lines(report.err) == 1u);
    BOOST_TEST(report.err.find(s.path("z.metrics.json") + ": more than 1000000 bytes, the cap on "
                                                          "a measured pack's file") !=
               std::string::npos);
    BOOST_TEST(!fs::exists(s.dir / "r"));

    sgmp::testing::write_text(s.dir / "manifest.csv",
                              "role,group,count,seed,seconds,path\n"
                              "candidate,c,300,1,0.1,a.xyz\nreference,DEM,300,2,20,b.xyz\n");
    const Run crossval = s.run("crossval --no-voronoi --manifest '" + s.path("manifest.csv") +
                                   "' --metrics /dev/zero --out '" + s.path("cv") + "'",
                               cap);
    BOOST_TEST_INFO("stderr: " << crossval.err);
    BOOST_TEST(crossval.status == 1);
    BOOST_TEST(lines(crossval.err) == 1u);
    BOOST_TEST(crossval.err ==
               "sgmp-compare: /dev/zero: more than 1000000 bytes, the cap on a batch summary\n");
    // A sparse file of 8 GB: refused from its size, with the real cap.
    sgmp::testing::write_text(s.dir / "sparse.csv", "");
    fs::resize_file(s.dir / "sparse.csv", std::uintmax_t{8} << 30);
    const Run sparse =
        s.run("crossval --no-voronoi --manifest '" + s.path("manifest.csv") + "' --metrics '" +
              s.path("sparse.csv") + "' --out '" + s.path("cv") + "'");
    BOOST_TEST(sparse.status == 1);
    BOOST_TEST(sparse.err == "sgmp-compare: " + s.path("sparse.csv") +
                                 ": 8589934592 bytes, more than the cap of 268435456 bytes on a "
                                 "batch summary\n");
}

// Finding 14: a 16 MiB binary line made one error line of 64 MB. Now a short excerpt.
BOOST_AUTO_TEST_CASE(an_error_about_a_long_binary_line_is_short) {
    const Scratch s;
    sgmp::testing::write_text(
        s.dir / "bin.xyz", std::string((std::size_t{16} << 20) - 10, '\x01') + "\n1 0 0 0 0.5 0\n");
    const Run r = s.run("measure --no-voronoi " + kContainer + " --out '" + s.path("m") + "' '" +
                        s.path("bin.xyz") + "'");
    BOOST_TEST_INFO("stderr size: " << r.err.size());
    BOOST_TEST(r.status == 1);
    BOOST_TEST(lines(r.err) == 1u);
    BOOST_TEST(r.err.size() < 4000u);  // at most 1000 bytes of message, each escaped to <= 4
    BOOST_TEST(r.err.find("\\x01") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
