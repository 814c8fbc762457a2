// The extended XYZ reader parses particle lines in blocks, in fixed chunks, on any number
// of threads (ReadOptions::threads), and splits fields 16 characters at a time. These tests
// check that neither shows: packs and error messages are the same for every thread count
// and every placement of blanks and tabs.
#include <boost/test/unit_test.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "sgmp/pack/random.hpp"
#include "sgmp/pack/xyz_format.hpp"
#include "test_support.hpp"

using namespace sgmp;
using sgmp::testing::input_error_of;

namespace {

const std::string kHeader = "Properties=id:I:1:pos:R:3:radius:R:1:bin:I:1\n";
/// Thread counts tried: serial, the machine's two, and more threads than chunks in a block.
const std::vector<unsigned> kThreads = {1, 2, 3, 7, 40};

/// Lines "id x y z 0.01 0" for ids 1…count (particle k on file line k + 3).
std::vector<std::string> particle_lines(std::size_t count) {
    std::vector<std::string> lines;
    lines.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        const auto v = static_cast<double>(k);
        lines.push_back(std::to_string(k + 1) + " " + std::to_string(0.001 * v) + " " +
                        std::to_string(1e-6 * v) + " -" + std::to_string(0.5 * v) + " 0.01 0");
    }
    return lines;
}

std::string file_of(const std::vector<std::string>& lines, std::size_t claimed) {
    std::string text = std::to_string(claimed) + "\n" + kHeader;
    for (const auto& line : lines) {
        text += line;
        text += '\n';
    }
    return text;
}

PackRead read_with(const std::string& text, unsigned threads) {
    std::istringstream in(text);
    ReadOptions options;
    options.threads = threads;
    return read_xyz(in, "pack.xyz", options);
}

std::string error_with(const std::string& text, unsigned threads) {
    return input_error_of([&] { (void)read_with(text, threads); });
}

/// The error every thread count reports for `lines` (claimed count: their number, or
/// `claimed`); the test fails when two thread counts disagree.
std::string error_of(const std::vector<std::string>& lines, std::size_t claimed = 0) {
    const std::string text = file_of(lines, claimed == 0 ? lines.size() : claimed);
    const std::string serial = error_with(text, 1);
    for (const unsigned threads : kThreads) {
        BOOST_TEST(error_with(text, threads) == serial, "threads = " << threads);
    }
    return serial;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(parallel_read)

BOOST_AUTO_TEST_CASE(the_pack_does_not_depend_on_the_thread_count) {
    // 150,000 lines: three blocks of up to 65,536 lines, 37 chunks of 4096.
    const std::string text = file_of(particle_lines(150000), 150000);
    const PackRead serial = read_with(text, 1);
    BOOST_TEST_REQUIRE(serial.pack.particles.size() == 150000u);
    BOOST_TEST(serial.decimals.value() == 6);  // std::to_string writes 6 decimals
    for (const unsigned threads : kThreads) {
        const PackRead read = read_with(text, threads);
        BOOST_TEST_REQUIRE(read.pack.particles.size() == serial.pack.particles.size());
        bool same = read.decimals == serial.decimals;
        for (std::size_t k = 0; k < read.pack.particles.size(); ++k) {
            const Particle& a = read.pack.particles[k];
            const Particle& b = serial.pack.particles[k];
            same = same && a.id == b.id && (a.center.array() == b.center.array()).all() &&
                   a.radius == b.radius && a.color == b.color;
        }
        BOOST_TEST(same, "threads = " << threads);
    }
    BOOST_TEST(serial.pack.particles[149999].center.z() == -0.5 * 149999.0);
}

BOOST_AUTO_TEST_CASE(blanks_and_tabs_split_fields_at_any_offset) {
    // Runs of 1–40 blanks and tabs before, between and after the fields put field ends on
    // every position of the 16-character blocks; each value must come back exactly.
    Random random(11);
    const auto separators = [&](int least) {
        std::string run;
        const int length = least + static_cast<int>(random.below(40));
        for (int i = 0; i < length; ++i) {
            run += random.below(2) == 0 ? ' ' : '\t';
        }
        return run;
    };
    std::vector<Particle> expected;
    std::vector<std::string> lines;
    for (int k = 0; k < 3000; ++k) {
        const Particle p{k + 1, Vec3(random.uniform(-1, 1), random.uniform(-1, 1), k), 0.25, k % 7};
        std::string line = separators(0) + std::to_string(p.id);
        for (const double value : {p.center.x(), p.center.y(), p.center.z(), p.radius}) {
            line += separators(1) + format_number(value);
        }
        line += separators(1) + std::to_string(p.color) + separators(0);
        lines.push_back(line);
        expected.push_back(p);
    }
    const std::string text = file_of(lines, lines.size());
    for (const unsigned threads : {1u, 2u}) {
        const PackRead read = read_with(text, threads);
        BOOST_TEST_REQUIRE(read.pack.particles.size() == expected.size());
        int wrong = 0;
        for (std::size_t k = 0; k < expected.size(); ++k) {
            const Particle& a = read.pack.particles[k];
            const Particle& b = expected[k];
            wrong += a.id == b.id && (a.center.array() == b.center.array()).all() &&
                             a.radius == b.radius && a.color == b.color
                         ? 0
                         : 1;
        }
        BOOST_TEST(wrong == 0);
    }
    // A line of blanks and tabs only has no fields.
    BOOST_TEST(error_of({std::string(37, ' ') + "\t\t"}) ==
               "pack.xyz:3: expected 6 columns, found 0");
}

BOOST_AUTO_TEST_CASE(the_first_error_in_the_file_is_reported_for_every_thread_count) {
    const std::vector<std::string> good = particle_lines(140000);
    auto lines = good;
    // Two bad lines in different chunks of the second block: the earlier one is reported,
    // though the later one's chunk may be parsed first.
    lines[70000] = "70001 0 x 0 0.01 0";
    lines[100000] = "100001 0 y 0 0.01 0";
    BOOST_TEST(error_of(lines) == "pack.xyz:70003: coordinate 'x' is not a number");
    // A repeated id before the bad line wins over it, in the same block or an earlier one.
    lines[69000] = "12 0 0 0 0.01 0";
    BOOST_TEST(error_of(lines) == "pack.xyz:69003: id 12 repeats the id of line 14");
    lines[69000] = good[69000];
    lines[80000] = "12 0 0 0 0.01 0";  // a repeat after the bad line does not
    BOOST_TEST(error_of(lines) == "pack.xyz:70003: coordinate 'x' is not a number");
    // A bad value and a wrong column count are found in the chunk's own thread.
    lines = good;
    lines[5000] = "5001 0 0 0 -0.01 0";
    BOOST_TEST(error_of(lines) ==
               "pack.xyz:5003: particle 5001 has radius -0.01; a radius must be finite and > 0");
    lines[5000] = "5001 0 0 0 0.01";
    BOOST_TEST(error_of(lines) == "pack.xyz:5003: expected 6 columns, found 5");
    // A file shorter than its count ends after its last line, after its lines are checked.
    BOOST_TEST(error_of(good, 140001) ==
               "pack.xyz:140002: file ends after 140000 of 140001 "
               "particle lines");
    lines = good;
    lines[139999] = "1 0 0 0 0.01 0";
    BOOST_TEST(error_of(lines, 140001) == "pack.xyz:140002: id 1 repeats the id of line 3");
}

BOOST_AUTO_TEST_CASE(repeated_ids_are_found_in_any_range) {
    const auto with_ids = [](const std::vector<long long>& ids) {
        std::vector<std::string> lines;
        for (const long long id : ids) {
            lines.push_back(std::to_string(id) + " 0 0 0 0.01 0");
        }
        return lines;
    };
    BOOST_TEST(error_of(with_ids({1000000000000LL, 5, 1000000000000LL})) ==
               "pack.xyz:5: id 1000000000000 repeats the id of line 3");
    BOOST_TEST(error_of(with_ids({-7, 0, -7})) == "pack.xyz:5: id -7 repeats the id of line 3");
    BOOST_TEST(error_of(with_ids({0, 0})) == "pack.xyz:4: id 0 repeats the id of line 3");
    // An id first met beyond the table of small ids, met again once the table has grown
    // past it.
    std::vector<long long> ids{1000000};
    for (long long id = 1; id <= 300000; ++id) {
        ids.push_back(id);
    }
    ids.push_back(1000000);
    BOOST_TEST(error_of(with_ids(ids)) == "pack.xyz:300004: id 1000000 repeats the id of line 3");
    ids.pop_back();
    ids.push_back(1000001);  // and a new id there is no repeat
    BOOST_TEST(error_of(with_ids(ids)).empty());
}

BOOST_AUTO_TEST_SUITE_END()
