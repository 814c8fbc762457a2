// The readers' memory bounds (reliability findings 4-6 and 14): whole files read with a
// cap checked before reading, the xyz reader's block bounded in bytes, error lines that
// quote a short excerpt, and the crowding limit that keeps pair searches O(N).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/bounded_file.hpp"
#include "sgmp/pack/crowding.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/random.hpp"
#include "test_support.hpp"

using namespace sgmp;
using sgmp::testing::input_error_of;
using sgmp::testing::sphere;
using sgmp::testing::TestDirectory;
using sgmp::testing::write_text;
namespace fs = std::filesystem;

namespace {

/// The virtual memory the process maps now (bytes, /proc/self/statm).
std::size_t mapped_bytes() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0;
    statm >> pages;
    return pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

/// Runs `work` in a child whose address space may grow by at most `extra` bytes beyond what
/// it maps at the fork; its exit status: 0 when `work` returned, 3 when it ran out of memory
/// (std::bad_alloc), 4 on any other exception.
template <class Work>
int in_child_with_memory(std::size_t extra, Work&& work) {
    const pid_t pid = ::fork();
    BOOST_TEST_REQUIRE(pid >= 0);
    if (pid == 0) {
        ::alarm(60);
        const rlimit limit{mapped_bytes() + extra, mapped_bytes() + extra};
        ::setrlimit(RLIMIT_AS, &limit);
        int status = 0;
        try {
            work();
        } catch (const std::bad_alloc&) {
            status = 3;
        } catch (...) {
            status = 4;
        }
        ::_exit(status);
    }
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(memory_bounds)

// Finding 5: whole-file readers had no bound (`batch --merge /dev/zero`: std::bad_alloc;
// an 8 GB sparse file the same). The cap is checked before reading.
BOOST_AUTO_TEST_CASE(a_whole_file_read_refuses_what_is_over_its_cap_before_reading) {
    TestDirectory scratch("memory_bounds_whole_file");
    const fs::path small = scratch.path() / "small.csv";
    write_text(small, std::string(100, 'a'));
    BOOST_TEST(read_bounded_file(small, 100, "a test file") == std::string(100, 'a'));
    const std::string over =
        input_error_of([&] { (void)read_bounded_file(small, 99, "a test file"); });
    BOOST_TEST(over ==
               small.string() + ": 100 bytes, more than the cap of 99 bytes on a test file");

    // A sparse file of 8 GB: refused from its size, at once (no byte is read).
    const fs::path sparse = scratch.path() / "sparse.csv";
    write_text(sparse, "");
    fs::resize_file(sparse, std::uintmax_t{8} << 30);
    BOOST_TEST(input_error_of([&] {
                   (void)read_bounded_file(sparse, kMaxSummaryBytes, "a batch summary");
               }) == sparse.string() +
                         ": 8589934592 bytes, more than the cap of 268435456 "
                         "bytes on a batch summary");

    // A device without a size, directly or through a link: the read stops past the cap.
    const fs::path link = scratch.path() / "zero.metrics.json";
    fs::create_symlink("/dev/zero", link);
    for (const fs::path& path : {fs::path("/dev/zero"), link}) {
        BOOST_TEST(input_error_of([&] { (void)read_bounded_file(path, 1 << 20, "a test file"); }) ==
                   path.string() + ": more than 1048576 bytes, the cap on a test file");
    }
    BOOST_TEST(input_error_of([&] {
                   (void)read_bounded_file(scratch.path() / "none", 10, "x");
               }).find("cannot open for reading") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_environment_may_lower_a_cap_but_not_raise_it) {
    ::setenv("SGMP_MAX_FILE_BYTES", "1000", 1);
    BOOST_TEST(effective_cap(kMaxSmallFileBytes) == 1000u);
    ::setenv("SGMP_MAX_FILE_BYTES", "99999999999", 1);
    BOOST_TEST(effective_cap(kMaxSmallFileBytes) == kMaxSmallFileBytes);
    ::setenv("SGMP_MAX_FILE_BYTES", "12x", 1);
    BOOST_TEST(effective_cap(kMaxSmallFileBytes) == kMaxSmallFileBytes);
    ::unsetenv("SGMP_MAX_FILE_BYTES");
    BOOST_TEST(effective_cap(kMaxSmallFileBytes) == kMaxSmallFileBytes);
}

// Finding 14: a 16 MiB binary line quoted in an error made one line of 64 MB. The reason is
// cut to an excerpt that keeps its start and end.
BOOST_AUTO_TEST_CASE(an_error_quotes_at_most_a_short_excerpt_of_a_long_line) {
    const std::string line(std::size_t{16} << 20, '\x01');
    const InputError error("f.xyz", 3, "expected 'ITEM: TIMESTEP', found '" + line + "'");
    const std::string text = error.what();
    // At most kMaxReasonBytes bytes of the reason, each escaped to at most 4 bytes.
    BOOST_TEST(text.size() <= 4 * kMaxReasonBytes + 100);
    BOOST_TEST(text.rfind("f.xyz:3: expected 'ITEM: TIMESTEP', found '\\x01", 0) == 0u);
    BOOST_TEST(text.find(" bytes left out] ... ") != std::string::npos);
    BOOST_TEST(text.back() == '\'');
    BOOST_TEST(excerpt("short", 10) == "short");
    BOOST_TEST(excerpt(std::string(30, 'a'), 9) == "aaaaaa ... [21 bytes left out] ... aaa");
}

// Finding 6: 65,536 lines were buffered at once whatever their length: 60 lines of 15 MiB
// took 989 MB. Now the block stops at 8 MiB, and a gzip stream that inflates more than 100×
// past 4 MiB is refused (pack_file.cpp: pack text compresses about 3×): a gzip file of
// 8 lines of 15 MiB (120 MiB buffered before) is refused in a child allowed 80 MiB more
// address space than it maps (tolerance: the guard's 4 MiB, the block and the line being
// read; the old reader needs >= 120 MiB for the block alone).
BOOST_AUTO_TEST_CASE(long_gzip_lines_are_not_buffered_sixty_five_thousand_at_a_time) {
    TestDirectory scratch("memory_bounds_gzip");
    Pack pack;
    for (int i = 0; i < 8; ++i) {
        pack.particles.push_back(sphere(i + 1, -0.5 + 0.06 * i, -0.5, 0.0, 0.025));
    }
    write_pack_file(scratch.path() / "plain.xyz", pack, false);
    std::istringstream lines(sgmp::testing::read_bytes(scratch.path() / "plain.xyz"));
    const std::string padding((std::size_t{15} << 20) - 100, ' ');
    const fs::path bomb = scratch.path() / "long.xyz.gz";
    write_file_atomically(bomb, false, [&](std::ostream& out) {
        int k = 0;
        for (std::string line; std::getline(lines, line); ++k) {
            out << line << (k >= 2 ? padding : "") << '\n';
        }
    });
    BOOST_TEST(fs::file_size(bomb) < (std::uintmax_t{2} << 20));  // a bomb: small on disk
    const int status = in_child_with_memory(std::size_t{80} << 20, [&] {
        ReadOptions options;
        options.threads = 1;
        try {
            read_pack_file(bomb, options);
        } catch (const InputError& e) {
            if (std::string(e.what()).find("inflating more than 100 times") != std::string::npos) {
                return;
            }
        }
        throw std::runtime_error("not refused by the inflation guard");
    });
    BOOST_TEST(status == 0);
}

// Finding 6, second case: 20 M lines of one short sphere (388 KB gzipped) took 1.88 GB,
// since each line is a sphere kept. Lines of one repeated sphere compress about 500×: 2·10⁶
// of them (26 MB of text) are refused once 4 MiB have inflated, naming the ratio; 2·10⁵
// random spheres (18 MB of text, about 2.5× compressed) still read.
BOOST_AUTO_TEST_CASE(a_gzip_stream_of_repetition_is_refused_and_pack_text_is_not) {
    TestDirectory scratch("memory_bounds_inflation");
    const fs::path bomb = scratch.path() / "repeat.xyz.gz";
    write_file_atomically(bomb, false, [&](std::ostream& out) {
        out << "2000000\nProperties=species:S:1:pos:R:3:radius:R:1\n";
        for (int i = 0; i < 2000000; ++i) {
            out << "H 0 0 0 0.01\n";
        }
    });
    BOOST_TEST(fs::file_size(bomb) < (std::uintmax_t{1} << 20));
    try {
        read_pack_file(bomb);
        BOOST_FAIL("a stream of repetition was read");
    } catch (const InputError& e) {
        const std::string text = e.what();
        BOOST_TEST(text.find("repeat.xyz.gz: gzip data inflating more than 100 times") !=
                   std::string::npos);
        BOOST_TEST(text.find('\n') == std::string::npos);
    }
    Pack spheres;
    Random random(7);
    for (int i = 0; i < 200000; ++i) {
        spheres.particles.push_back(sphere(i + 1, random.uniform(-0.5, 0.5),
                                           random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5),
                                           0.001));
    }
    const fs::path text = scratch.path() / "random.xyz.gz";
    write_pack_file(text, spheres, false);
    BOOST_TEST(fs::file_size(text) > (std::uintmax_t{5} << 20));  // > 4 MiB inflated at < 4×
    BOOST_TEST(read_pack_file(text).particles.size() == 200000u);
}

// Finding 4: 8,000 spheres at one point made every pair pass O(N²) (3.0 GB, 38 s in
// measure). The crowding limit finds them in O(N log N), naming the first sphere.
BOOST_AUTO_TEST_CASE(clumped_centres_are_found_and_hard_spheres_pass) {
    std::vector<Particle> clump;
    for (int i = 0; i < 8000; ++i) {
        clump.push_back(sphere(i + 1, 0.0, 0.0, 0.0, 0.5));
    }
    const auto crowded = overcrowded_cube(clump);
    BOOST_TEST_REQUIRE(crowded.has_value());
    BOOST_TEST(crowded->index == 0u);
    BOOST_TEST(crowded->centres == 8000u);
    BOOST_TEST(crowded->cube_side == 1.0);

    // The limit itself: 51 centres in one cube pass, 52 do not (a clump after 20 spheres).
    std::vector<Particle> some;
    for (int i = 0; i < 20; ++i) {
        some.push_back(sphere(i + 1, 10.0 + 2.0 * i, 0.5, 0.5, 0.5));
    }
    for (int i = 0; i < 52; ++i) {
        some.push_back(sphere(100 + i, 0.1 + 0.01 * i, 0.5, 0.5, 0.5));
    }
    BOOST_TEST(overcrowded_cube(some)->index == 20u);
    BOOST_TEST(overcrowded_cube(some)->centres == 52u);
    some.pop_back();
    BOOST_TEST(!overcrowded_cube(some).has_value());

    // Hard spheres never reach it: a dense fcc lattice (the densest packing, every sphere
    // touching 12), also shifted off the cubes' corners.
    for (const double shift : {0.0, 0.37}) {
        std::vector<Particle> fcc;
        const double a = std::sqrt(2.0);  // cubic cell of fcc with touching diameter 1
        for (int x = 0; x < 8; ++x) {
            for (int y = 0; y < 8; ++y) {
                for (int z = 0; z < 8; ++z) {
                    for (const auto& [u, v, w] : {std::array{0.0, 0.0, 0.0},
                                                  {0.5, 0.5, 0.0},
                                                  {0.5, 0.0, 0.5},
                                                  {0.0, 0.5, 0.5}}) {
                        fcc.push_back(sphere(static_cast<std::int64_t>(fcc.size() + 1),
                                             a * (x + u) + shift, a * (y + v), a * (z + w), 0.5));
                    }
                }
            }
        }
        BOOST_TEST(!overcrowded_cube(fcc).has_value());
    }
}

BOOST_AUTO_TEST_SUITE_END()
