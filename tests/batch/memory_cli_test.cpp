// Reliability findings 5 and 14 at `sgmp batch`: the summaries merged are read with a cap
// checked before reading, and a failure is one line that never says "std::bad_alloc".
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <string>

#include "test_support.hpp"

namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(batch_memory)

// `sgmp batch --merge /dev/zero` ended in "sgmp: std::bad_alloc"; so did a sparse summary
// of 8 GB. Now one line naming the file and the cap, exit 1, and no summary written.
BOOST_AUTO_TEST_CASE(merged_summaries_are_read_with_a_cap) {
    const sgmp::testing::ProgramScratch s("batch-memory-merge", SGMP_EXECUTABLE);
    const auto one_line = [](const std::string& text) {
        return std::count(text.begin(), text.end(), '\n') == 1;
    };
    // SGMP_MAX_FILE_BYTES lowers the cap so that the device is read only 1 MB far.
    const auto zero = s.run("batch --merge /dev/zero --summary '" + s.path("all.csv") + "'",
                            "SGMP_MAX_FILE_BYTES=1000000");
    BOOST_TEST_INFO("stderr: " << zero.err);
    BOOST_TEST(zero.status == 1);
    BOOST_TEST(one_line(zero.err));
    BOOST_TEST(zero.err ==
               "sgmp: /dev/zero: more than 1000000 bytes, the cap on a batch summary\n");
    sgmp::testing::write_text(s.dir / "sparse.csv", "");
    fs::resize_file(s.dir / "sparse.csv", std::uintmax_t{8} << 30);
    const auto sparse =
        s.run("batch --merge '" + s.path("sparse.csv") + "' --summary '" + s.path("all.csv") + "'");
    BOOST_TEST(sparse.status == 1);
    BOOST_TEST(sparse.err == "sgmp: " + s.path("sparse.csv") +
                                 ": 8589934592 bytes, more than the cap of 268435456 bytes on a "
                                 "batch summary\n");
    BOOST_TEST(!fs::exists(s.dir / "all.csv"));
}

BOOST_AUTO_TEST_SUITE_END()
