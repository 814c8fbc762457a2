#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/executables.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>

#include "sgmp/pack/atom_types.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "sgmp/pack/output_frame.hpp"
#include "sgmp/pack/pack_extent.hpp"
#include "sgmp/pack/pack_format.hpp"
#include "sgmp/pack/random.hpp"

#include "sgmp/pack/atomic_file.hpp"
#include "test_support.hpp"

using namespace sgmp;
using namespace sgmp::testing;
namespace fs = std::filesystem;

namespace {

Pack small_pack() {
    Pack pack;
    pack.metadata.set("generator", "sgmp");
    pack.metadata.set_integer("seed", 3);
    pack.particles = {Particle{1, Vec3(0.1, -0.5, 0.2), 0.05, 3},
                      Particle{2, Vec3(-0.1, -0.5, 0.2), 0.05, 4}};
    return pack;
}

std::size_t entries_in(const fs::path& directory) {
    return static_cast<std::size_t>(
        std::distance(fs::directory_iterator(directory), fs::directory_iterator()));
}

/// Writes `target` (1 MB of incompressible digits) in a child process whose file size
/// limit is 64 kB, as on a full disk. Returns the child's message and sets `status` to its
/// exit status, or to -1 when it did not end within 20 s (a hang).
std::string write_past_the_size_limit(const fs::path& target, int& status) {
    int fds[2];
    BOOST_TEST_REQUIRE(::pipe(fds) == 0);
    const pid_t pid = ::fork();
    BOOST_TEST_REQUIRE(pid >= 0);
    if (pid == 0) {
        ::close(fds[0]);
        std::signal(SIGXFSZ, SIG_IGN);  // the write then fails with EFBIG, as on ENOSPC
        const rlimit limit{64 * 1024, 64 * 1024};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        ::alarm(20);
        std::string message = "no error";
        try {
            write_file_atomically(target, false, [](std::ostream& out) {
                Random random(7);
                for (int i = 0; i < 100000; ++i) {
                    out << random.below(10000000000ULL) << '\n';
                }
            });
        } catch (const std::exception& error) {
            message = error.what();
        }
        (void)!::write(fds[1], message.data(), message.size());
        ::_exit(message == "no error" ? 0 : 1);
    }
    ::close(fds[1]);
    std::string message;
    char buffer[512];
    ssize_t got = 0;
    while ((got = ::read(fds[0], buffer, sizeof buffer)) > 0) {
        message.append(buffer, static_cast<std::size_t>(got));
    }
    ::close(fds[0]);
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return message;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pack_file)

BOOST_AUTO_TEST_CASE(sigint_in_the_middle_of_a_write_removes_the_temporary_and_exits_130) {
    // In a child: the interrupt handler is installed, a .gz and a directory are half
    // written, then SIGINT arrives. The child must exit 130 and leave nothing behind.
    TestDirectory scratch("pack_file_interrupt");
    for (const bool directory : {false, true}) {
        const pid_t pid = ::fork();
        BOOST_TEST_REQUIRE(pid >= 0);
        if (pid == 0) {
            ::alarm(20);
            install_interrupt_handler("pack_tests");
            const auto interrupt = [] {
                ::kill(::getpid(), SIGINT);
                ::pause();  // the watcher thread exits the process
            };
            if (directory) {
                write_directory_atomically(scratch.path() / "out", false, [&](const fs::path& d) {
                    write_text(d / "part.txt", "half of the output");
                    interrupt();
                });
            } else {
                write_file_atomically(scratch.path() / "big.xyz.gz", false, [&](std::ostream& out) {
                    out << std::string(1 << 20, 'x');
                    interrupt();
                });
            }
            ::_exit(0);
        }
        int raw = 0;
        ::waitpid(pid, &raw, 0);
        BOOST_TEST_INFO(std::string(directory ? "directory" : "file"));
        BOOST_TEST((WIFEXITED(raw) ? WEXITSTATUS(raw) : -1) == 130);
        BOOST_TEST(entries_in(scratch.path()) == 0u);
    }
}

// A .vtk pack and its container are one output. With --force over an existing pair, a
// failure or an interrupt once left the old particles without a container: the new
// container was already in place and was then removed. Now both are renamed together at
// the end, and a failed rename puts the old container back.
BOOST_AUTO_TEST_CASE(a_failed_vtk_write_over_a_pair_keeps_the_old_pair) {
    TestDirectory scratch("pack_file_vtk_pair");
    const fs::path particles = scratch.path() / "o.vtk";
    const fs::path container = scratch.path() / "o.container.vtk";
    fs::create_directories(particles / "x");  // the particles' rename fails (a directory)
    write_text(container, "old container");
    BOOST_CHECK_THROW(write_pack_as(particles, small_pack(), PackFormat::vtk, WriteOptions{true}),
                      std::runtime_error);
    BOOST_TEST(read_bytes(container) == "old container");
    BOOST_TEST(entries_in(scratch.path()) == 2u);  // no temporary, no backup
    fs::remove_all(particles);
    write_text(particles, "old particles");
    write_pack_as(particles, small_pack(), PackFormat::vtk, WriteOptions{true});
    BOOST_TEST(read_bytes(container) != "old container");
    BOOST_TEST(read_bytes(particles) != "old particles");
    BOOST_TEST(entries_in(scratch.path()) == 2u);
}

BOOST_AUTO_TEST_CASE(an_interrupt_leaves_the_old_pair_or_the_new_one) {
    TestDirectory scratch("pack_file_pair_interrupt");
    const fs::path first = scratch.path() / "o.container.vtk";
    const fs::path second = scratch.path() / "o.vtk";
    const auto run_child = [](const std::function<void()>& body) {
        const pid_t pid = ::fork();
        BOOST_TEST_REQUIRE(pid >= 0);
        if (pid == 0) {
            ::alarm(20);
            install_interrupt_handler("pack_tests");
            body();
            ::_exit(0);
        }
        int raw = 0;
        ::waitpid(pid, &raw, 0);
        return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    };
    const auto interrupt = [] {
        ::kill(::getpid(), SIGTERM);
        ::pause();  // the watcher thread exits the process
    };
    // While the second file is produced: nothing is renamed yet, the old pair stays.
    write_text(first, "old 1");
    write_text(second, "old 2");
    BOOST_TEST(run_child([&] {
                   write_files_atomically({{first, [](std::ostream& out) { out << "new 1"; }},
                                           {second,
                                            [&](std::ostream& out) {
                                                out << "new 2";
                                                interrupt();
                                            }}},
                                          true);
               }) == 130);
    BOOST_TEST(read_bytes(first) == "old 1");
    BOOST_TEST(read_bytes(second) == "old 2");
    BOOST_TEST(entries_in(scratch.path()) == 2u);
    // A signal while the pair is renamed waits until both renames are done.
    const fs::path done = scratch.path() / "done";
    BOOST_TEST(run_child([&] {
                   run_uninterrupted([&] {
                       ::kill(::getpid(), SIGTERM);
                       ::usleep(200000);  // the watcher has the signal by now, and waits
                       write_text(done, "both renamed");
                   });
                   ::pause();
               }) == 130);
    BOOST_TEST(read_bytes(done) == "both renamed");
}

BOOST_AUTO_TEST_CASE(a_full_disk_fails_a_compressed_or_plain_write_in_one_line) {
    // The gzip compressor once retried a failed write for ever (100 % CPU).
    TestDirectory scratch("pack_file_full_disk");
    for (const std::string name : {"big.xyz.gz", "big.xyz"}) {
        int status = 0;
        const std::string message = write_past_the_size_limit(scratch.path() / name, status);
        BOOST_TEST_INFO(name);
        BOOST_TEST(status == 1);
        BOOST_TEST(message == (scratch.path() / name).string() + ": write failed: File too large");
        BOOST_TEST(entries_in(scratch.path()) == 0u);  // neither target nor temporary
    }
}

BOOST_AUTO_TEST_CASE(plain_and_gzip_files_read_back_the_same) {
    TestDirectory scratch("pack_file_round_trip");
    const Pack pack = small_pack();
    write_pack_file(scratch.path() / "a.xyz", pack, false);
    write_pack_file(scratch.path() / "a.xyz.gz", pack, false);
    const std::string gz = read_bytes(scratch.path() / "a.xyz.gz");
    BOOST_TEST_REQUIRE(gz.size() > 2u);
    BOOST_TEST(static_cast<unsigned char>(gz[0]) == 0x1fu);
    const Pack plain = read_pack_file(scratch.path() / "a.xyz");
    const Pack compressed = read_pack_file(scratch.path() / "a.xyz.gz");
    BOOST_TEST(plain.particles.size() == 2u);
    BOOST_TEST(compressed.particles[1].center.x() == -0.1);
    BOOST_TEST(compressed.metadata.entries() == plain.metadata.entries());
    // Compression is deterministic: the same pack gives the same bytes.
    write_pack_file(scratch.path() / "b.xyz.gz", pack, false);
    BOOST_TEST(read_bytes(scratch.path() / "b.xyz.gz") == gz);
}

// A z-up file in metres: positions R·(L·c) with R(x, y, z) = (x, −z, y), the box turned
// and scaled, and reading it back turns it back to y up (scale kept, exact: L is a power
// of two so every product is exact).
BOOST_AUTO_TEST_CASE(an_output_frame_turns_and_scales_and_reads_back_y_up) {
    TestDirectory scratch("pack_file_frame");
    const Pack pack = small_pack();
    OutputFrame frame;
    frame.up = UpAxis::Z;
    frame.length_scale = 0.25;
    frame.length_unit = "m";
    frame.density = 2500.0;
    const Pack written = in_output_frame(pack, frame);
    for (std::size_t i = 0; i < pack.particles.size(); ++i) {
        const Vec3 c = pack.particles[i].center;
        BOOST_TEST(written.particles[i].center == Vec3(0.25 * c.x(), -0.25 * c.z(), 0.25 * c.y()));
        BOOST_TEST(written.particles[i].radius == 0.25 * pack.particles[i].radius);
    }
    const Box box = container_box(written);
    BOOST_TEST(box.lo.z() == 0.25 * -0.625);  // the floor
    BOOST_TEST(box.lo.y() == -0.25 * 0.625);
    BOOST_TEST(box.hi.y() == 0.25 * 0.625);
    for (const char* name : {"f.xyz", "f.data"}) {
        write_pack_as(scratch.path() / name, written, *format_from_extension(scratch.path() / name),
                      WriteOptions{});
        const Pack back = read_pack_file(scratch.path() / name);
        for (std::size_t i = 0; i < pack.particles.size(); ++i) {
            BOOST_TEST(back.particles[i].center == 0.25 * pack.particles[i].center);
        }
        BOOST_TEST(back.metadata.get("up_axis").value_or("") == "y");
        BOOST_TEST(!back.metadata.contains("box"));
        BOOST_TEST(back.metadata.get("length_unit").value_or("") == "m");
    }
    BOOST_TEST(read_bytes(scratch.path() / "f.data").find(" 2500 ") != std::string::npos);
}

// Frames and what they must not break: a blend's LAMMPS types survive scaling; a file
// already in metres written in millimetres is scaled by their ratio; a pack without a
// container key, written z up to a data file (whose reader takes the box as container),
// reads back with the container it had.
BOOST_AUTO_TEST_CASE(output_frames_keep_types_scale_once_and_keep_the_container) {
    TestDirectory scratch("pack_file_frames");
    Pack blend;
    blend.metadata.set("diameter", "0.2");
    blend.metadata.set("size_modes", "1:0.5,0.5:0.5");
    blend.particles = {Particle{1, Vec3(0.0, -0.5, 0.0), 0.1, 0},
                       Particle{2, Vec3(0.3, -0.55, 0.0), 0.05, 0}};
    OutputFrame metres;
    metres.length_scale = 0.004;
    metres.length_unit = "m";
    const Pack m = in_output_frame(blend, metres);
    BOOST_TEST((atom_types(m).type == std::vector<int>{1, 2}));
    OutputFrame millimetres;
    millimetres.length_scale = 4.0;
    millimetres.length_unit = "mm";
    const Pack mm = in_output_frame(m, millimetres);
    BOOST_TEST(mm.particles[0].radius == blend.particles[0].radius * 4.0,
               boost::test_tools::tolerance(1e-15));
    BOOST_TEST(mm.metadata.get("length_scale").value_or("") == "4");
    Pack plain;
    plain.particles = blend.particles;
    OutputFrame up;
    up.up = UpAxis::Z;
    write_pack_as(scratch.path() / "z.data", in_output_frame(plain, up), PackFormat::lammps_data,
                  WriteOptions{});
    const Pack back = read_pack_file(scratch.path() / "z.data");
    BOOST_TEST(back.metadata.get("container").value_or("") == Container{}.to_string());
    BOOST_TEST(back.particles[1].center == plain.particles[1].center);
}

BOOST_AUTO_TEST_CASE(dump_files_are_detected) {
    TestDirectory scratch("pack_file_dump");
    write_text(scratch.path() / "pour.dump",
               "\nITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff ff\n"
               "0.4 0.6\n0.4 1\n0.4 0.6\nITEM: ATOMS id x y z diameter\n1 0.5 0.5 0.5 0.2\n");
    const Pack pack = read_pack_file(scratch.path() / "pour.dump");
    BOOST_TEST(pack.particles.at(0).radius == 0.1);
    // The sphere reaches the box's sides and floor: the box is its container.
    BOOST_TEST(pack.metadata.get("container").value_or("") == "0.4 0.6 0.4 0.6 0.4");
}

BOOST_AUTO_TEST_CASE(unreadable_and_corrupt_files) {
    TestDirectory scratch("pack_file_errors");
    const fs::path missing = scratch.path() / "missing.xyz";
    BOOST_TEST(input_error_of([&] { read_pack_file(missing); }) ==
               missing.string() + ": cannot open for reading");
    const fs::path empty = scratch.path() / "empty.xyz";
    write_text(empty, "");
    BOOST_TEST(input_error_of([&] { read_pack_file(empty); }) == empty.string() + ": empty file");
    const fs::path corrupt = scratch.path() / "corrupt.xyz.gz";
    write_text(corrupt, std::string("\x1f\x8b\x08\x00garbage", 11));
    BOOST_TEST(input_error_of([&] {
                   read_pack_file(corrupt);
               }).find("corrupt or truncated gzip data") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_vtk_file_is_refused_as_output_only) {
    // VTK is written for ParaView, never read: a pack written as .vtk is refused in one
    // line that says so (was: "expected the particle count").
    TestDirectory scratch("pack_file_vtk_in");
    Pack pack;
    pack.particles.push_back(Particle{1, Vec3(0.0, 0.0, 0.0), 0.1, 0});
    const fs::path vtk = scratch.path() / "p.vtk";
    write_pack_as(vtk, pack, PackFormat::vtk, WriteOptions{});
    BOOST_TEST(input_error_of([&] { read_pack_file(vtk); }) ==
               vtk.string() +
                   ":1: a VTK file: VTK is an output format only (for ParaView); read the "
                   "extended XYZ, dump or data file it was converted from");
    const fs::path vtp = scratch.path() / "p.vtp";
    write_pack_as(vtp, pack, PackFormat::vtp, WriteOptions{});
    BOOST_TEST(input_error_of([&] { read_pack_file(vtp); }).find(":1: a VTK file") !=
               std::string::npos);
}

// The binary XML file holds the doubles exactly: its appended blocks, read back by hand
// (UInt64 byte count, then the values), give the pack's centres and radii bit for bit.
BOOST_AUTO_TEST_CASE(a_vtp_file_holds_the_exact_doubles) {
    TestDirectory scratch("pack_file_vtp");
    Pack pack;
    pack.particles.push_back(Particle{7, Vec3(0.1, -0.2, 1.0 / 3.0), 0.125, 4});
    pack.particles.push_back(Particle{9, Vec3(-0.3, 0.45, 2.0 / 7.0), 0.0625, 2});
    const fs::path vtp = scratch.path() / "p.vtp";
    write_pack_as(vtp, pack, PackFormat::vtp, WriteOptions{});
    const std::string bytes = read_bytes(vtp);
    const std::size_t start = bytes.find("   _") + 4;
    const auto block = [&](std::size_t offset, std::size_t n, auto* values) {
        std::uint64_t count = 0;
        std::memcpy(&count, bytes.data() + start + offset, sizeof count);
        BOOST_TEST(count == n * sizeof(*values));
        std::memcpy(values, bytes.data() + start + offset + sizeof count, count);
        return offset + sizeof count + count;
    };
    double radius[2];
    std::int64_t id[2];
    std::int32_t bin[2];
    double points[6];
    std::size_t offset = block(0, 2, radius);
    offset = block(offset, 2, id);
    offset = block(offset, 2, bin);
    offset = block(offset, 6, points);
    BOOST_TEST(radius[0] == 0.125);
    BOOST_TEST(radius[1] == 0.0625);
    BOOST_TEST(id[0] == 7);
    BOOST_TEST(id[1] == 9);
    BOOST_TEST(bin[0] == 4);
    BOOST_TEST(points[2] == 1.0 / 3.0);
    BOOST_TEST(points[5] == 2.0 / 7.0);
    BOOST_TEST(bytes.find("offset=\"" + std::to_string(offset) + "\"") != std::string::npos);
    BOOST_TEST(fs::exists(scratch.path() / "p.container.vtp"));
}

BOOST_AUTO_TEST_CASE(existing_files_are_kept_without_overwrite) {
    TestDirectory scratch("pack_file_keep");
    const fs::path target = scratch.path() / "keep.xyz";
    write_text(target, "precious");
    BOOST_CHECK_THROW(write_pack_file(target, small_pack(), false), std::runtime_error);
    BOOST_TEST(read_bytes(target) == "precious");
    write_pack_file(target, small_pack(), true);
    BOOST_TEST(read_pack_file(target).particles.size() == 2u);
    BOOST_TEST(entries_in(scratch.path()) == 1u);
}

BOOST_AUTO_TEST_CASE(a_failed_write_leaves_nothing_behind) {
    TestDirectory scratch("pack_file_atomic");
    const fs::path target = scratch.path() / "half.xyz";
    BOOST_CHECK_THROW(write_file_atomically(target, false,
                                            [](std::ostream& out) {
                                                out << "partial";
                                                throw std::runtime_error("simulated failure");
                                            }),
                      std::runtime_error);
    BOOST_TEST(entries_in(scratch.path()) == 0u);

    const fs::path report = scratch.path() / "report";
    BOOST_CHECK_THROW(write_directory_atomically(report, false,
                                                 [](const fs::path& directory) {
                                                     write_text(directory / "a.txt", "x");
                                                     throw std::runtime_error("simulated");
                                                 }),
                      std::runtime_error);
    BOOST_TEST(entries_in(scratch.path()) == 0u);
    write_directory_atomically(
        report, false, [](const fs::path& directory) { write_text(directory / "a.txt", "x"); });
    BOOST_TEST(read_bytes(report / "a.txt") == "x");
    BOOST_CHECK_THROW(write_directory_atomically(report, false, [](const fs::path&) {}),
                      std::runtime_error);
    BOOST_TEST(fs::exists(report / "a.txt"));
}

BOOST_AUTO_TEST_CASE(unwritable_targets_are_refused_before_any_work) {
    TestDirectory scratch("pack_file_unwritable");
    const fs::path blocker = scratch.path() / "file";
    write_text(blocker, "x");
    BOOST_CHECK_THROW(check_writable(blocker / "sub" / "pack.xyz", false), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(a_program_found_by_a_relative_name_runs_from_any_directory) {
    // `--liggghts ./x` must not be looked up again inside the pour's temporary directory.
    const auto here = std::filesystem::current_path();
    const auto dir = std::filesystem::temp_directory_path() / "sgmp-exe-test";
    std::filesystem::create_directories(dir);
    write_text(dir / "tool", "#!/bin/sh\n");
    std::filesystem::permissions(dir / "tool", std::filesystem::perms::owner_all);
    std::filesystem::current_path(dir);
    const auto found = find_executable("./tool");
    std::filesystem::current_path(here);
    BOOST_TEST_REQUIRE(found.has_value());
    BOOST_TEST(found->is_absolute());
    BOOST_TEST(std::filesystem::equivalent(*found, dir / "tool"));
    const auto sh = find_executable("sh");  // on $PATH
    BOOST_TEST_REQUIRE(sh.has_value());
    BOOST_TEST(sh->is_absolute());
    std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
