// Reliability findings 5 and 7 at `sgmp pack`: files read whole have a cap checked before
// reading (a read failure is reported, not swallowed), and a wide size ratio packs in O(N)
// memory. (Running out of memory, one line naming what was being built: cli_test.cpp.)
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <string>

#include "test_support.hpp"

namespace fs = std::filesystem;

namespace {

struct Scratch : sgmp::testing::ProgramScratch {
    Scratch()
        : ProgramScratch(
              "engine-memory-" + boost::unit_test::framework::current_test_case().p_name.get(),
              SGMP_EXECUTABLE) {}
};

}  // namespace

BOOST_AUTO_TEST_SUITE(cli)

// An 8 GB sparse --config file: the read failure was swallowed and the error shown was
// "--count is required"; an 8 GB sparse --size-distribution file ended in std::bad_alloc.
// Both are now refused from their size, before a byte is read: one line, exit 1.
BOOST_AUTO_TEST_CASE(sparse_files_of_8_gb_are_refused_before_reading) {
    const Scratch s;
    for (const std::string name : {"big.toml", "big.csv"}) {
        sgmp::testing::write_text(s.dir / name, "");
        fs::resize_file(s.dir / name, std::uintmax_t{8} << 30);
    }
    const auto config =
        s.run("pack --config '" + s.path("big.toml") + "' --out '" + s.path("p.xyz") + "'");
    BOOST_TEST(config.status == 1);
    BOOST_TEST(config.err == "sgmp: --config " + s.path("big.toml") +
                                 ": 8589934592 bytes, more than the cap of 16777216 bytes on a "
                                 "config file\n");
    const auto sizes = s.run("pack --arrangement small-dense --count 100 --size-distribution '" +
                             s.path("big.csv") + "' --out '" + s.path("p.xyz") + "'");
    BOOST_TEST(sizes.status == 1);
    BOOST_TEST(sizes.err == "sgmp: --size-distribution " + s.path("big.csv") +
                                ": 8589934592 bytes, more than the cap of 16777216 bytes on a "
                                "size distribution file\n");
    BOOST_TEST(!fs::exists(s.dir / "p.xyz"));
}

// A size ratio of 1000 ran out of memory in SettledGrid::insert (dense layers of cells of
// the small diameter: ~10⁹ cells per large sphere). Within 1 GB of address space it now
// packs. Tolerance: the run needs less than 50 MB of address space (it packs under
// `ulimit -v 50000`, peak RSS ~10 MB); 1 GB is 20 times that, so only a grid that grows with
// the ratio fails, as the dense grid did (it exits 1 out of memory under this limit).
BOOST_AUTO_TEST_CASE(a_size_ratio_of_1000_packs_within_bounded_memory) {
    const Scratch s;
    const auto r = s.run(
        "pack --arrangement loose-random --count 200 --size-modes "
        "1:0.5,0.001:0.5 --seed 1 --out '" +
            s.path("w.xyz") + "'",
        "ulimit -v 1000000;");
    BOOST_TEST_INFO("stderr: " << r.err);
    BOOST_TEST(r.status == 0);
    BOOST_TEST(r.out.find("overlaps=0") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
