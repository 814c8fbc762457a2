// Faults of `sgmp-reference pour`, through the real executable with fake `liggghts`
// programs first on PATH. Each fault must give a one-line message, a non-zero exit and
// no pack file.
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "run_program.hpp"
#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/metadata.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace sgmp::reference::testing;

namespace {

const std::string kExe = SGMP_REFERENCE_EXE;
const std::string kBanner = "echo 'LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0, fake for tests)'\n";

/// A directory holding a fake `liggghts`, put first on PATH, and where outputs go.
struct FakeLiggghts {
    fs::path dir = fresh_directory("sgmp-ref-fake");
    fs::path out = dir / "pack.xyz";

    explicit FakeLiggghts(const std::string& body) {
        fs::create_directory(dir / "bin");
        write_script(dir / "bin" / "liggghts", body);
    }
    ~FakeLiggghts() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    [[nodiscard]] std::string path() const {
        const char* system_path = std::getenv("PATH");
        return (dir / "bin").string() + ":" + (system_path ? system_path : "/usr/bin:/bin");
    }
    ProgramRun pour(std::vector<std::string> extra = {}) const {
        ProgramOptions options;
        options.args = {"pour", "--count", "150", "--seed", "1", "--out", out.string()};
        options.args.insert(options.args.end(), extra.begin(), extra.end());
        options.path = path();
        return run_program(kExe, options);
    }
};

std::string first_line(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

/// True once process `pid` has ended (gone, or a zombie awaiting its reaper). Polls up to
/// ten seconds: the group is sent SIGTERM and, three seconds later, SIGKILL.
bool process_ended(const std::string& pid_file) {
    std::ifstream in(pid_file);
    long pid = 0;
    in >> pid;
    BOOST_TEST_REQUIRE(pid > 0);
    for (int i = 0; i < 200; ++i) {
        std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
        std::string pid_text, name, state;
        if (!(stat >> pid_text >> name >> state) || state == "Z") {
            return true;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
}

/// A fake that starts and then hangs; its `sleep` child records its pid.
std::string hanging_fake(const fs::path& dir, const std::string& before = "") {
    return kBanner + before + "sleep 600 &\necho $! > '" + (dir / "sleep.pid").string() +
           "'\ntouch '" + (dir / "started").string() + "'\nwait\n";
}

/// A dump of 150 spheres of the sizing rule's diameter standing apart in a grid on the
/// floor, layer upon layer; `edit` may then move sphere 0 (x, y, z) and sphere 1.
std::string settled_dump(const std::function<void(std::vector<sgmp::Vec3>&)>& edit = {}) {
    const double d = sgmp::diameter_for_count(150);
    std::vector<sgmp::Vec3> centers;
    for (int i = 0; i < 150; ++i) {
        const int layer = i / 16;
        const int row = (i % 16) / 4;
        const int column = i % 4;
        centers.emplace_back(-0.625 + d * (0.5 + 1.01 * column), -0.625 + d * (0.5 + 1.01 * layer),
                             -0.625 + d * (0.5 + 1.01 * row));
    }
    if (edit) {
        edit(centers);
    }
    std::string text =
        "ITEM: TIMESTEP\n1000\nITEM: NUMBER OF ATOMS\n150\nITEM: BOX BOUNDS ff ff ff\n"
        "-0.625 0.625\n-0.625 5\n-0.625 0.625\nITEM: ATOMS id type x y z radius vx vy vz\n";
    for (int i = 0; i < 150; ++i) {
        text += std::to_string(i + 1) + " 1 " + sgmp::format_number(centers[i].x()) + " " +
                sgmp::format_number(centers[i].y()) + " " + sgmp::format_number(centers[i].z()) +
                " " + sgmp::format_number(d / 2.0) + " 0 0 0\n";
    }
    return text;
}

/// A fake LIGGGHTS that reports a settled pour of 150 and leaves `dump` as its result.
std::string settled_fake(const fs::path& dump) {
    return kBanner +
           "echo 'SGMP-PARAMETERS timestep 1e-4 rayleigh_time 1e-3 step_cap 1000'\n"
           "echo 'SGMP-INSERTED 150'\necho 'SGMP-SETTLE 1000 1e-08 1e-06'\n"
           "cp '" +
           dump.string() + "' final.dump\necho 'SGMP-RESULT settled 1000 1e-08'\necho SGMP-DONE\n";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(cli_faults)

BOOST_AUTO_TEST_CASE(impossible_liggghts_results_are_refused_before_writing) {
    FakeLiggghts fake("");
    const fs::path dump = fake.dir / "result.dump";
    write_script(fake.dir / "bin" / "liggghts", settled_fake(dump));
    const double d = sgmp::diameter_for_count(150);
    {  // a sound result is written
        std::ofstream(dump) << settled_dump();
        const ProgramRun run = fake.pour({"--quiet"});
        BOOST_TEST(run.exit_code == 0, run.stderr_text);
        BOOST_TEST(fs::exists(fake.out));
        fs::remove(fake.out);
    }
    {  // a sphere 0.99 d outside the container (through the wall at x = 0.625)
        std::ofstream(dump) << settled_dump(
            [&](std::vector<sgmp::Vec3>& c) { c[0].x() = 0.625 - d / 2 + 0.99 * d; });
        const ProgramRun run = fake.pour({"--quiet"});
        BOOST_TEST(run.exit_code == 1);
        BOOST_TEST(first_line(run.stderr_text)
                           .find("sgmp-reference: the LIGGGHTS result has a sphere 0.99") == 0u,
                   run.stderr_text);
        BOOST_TEST(first_line(run.stderr_text).find("a settled pour stays within 0.05 d") !=
                   std::string::npos);
        BOOST_TEST(!fs::exists(fake.out));
    }
    {  // a truncated result: named by its file name, not the removed work directory's path
        std::string text = settled_dump();
        text.erase(text.rfind('\n', text.size() - 2) + 1);  // the last atom line
        std::ofstream(dump) << text;
        const ProgramRun run = fake.pour({"--quiet"});
        BOOST_TEST(run.exit_code == 1);
        BOOST_TEST(
            first_line(run.stderr_text)
                    .find("sgmp-reference: cannot read the LIGGGHTS result: final.dump:") == 0u,
            run.stderr_text);
        BOOST_TEST(first_line(run.stderr_text).find('/') == std::string::npos, run.stderr_text);
        BOOST_TEST(!fs::exists(fake.out));
    }
    {  // reported settled, but a sphere moves at 1000 m/s
        std::string text = settled_dump();
        const std::string first = " 0 0 0\n";
        text.replace(text.find(first), first.size(), " 1000 0 0\n");
        std::ofstream(dump) << text;
        const ProgramRun run = fake.pour({"--quiet"});
        BOOST_TEST(run.exit_code == 1);
        BOOST_TEST(first_line(run.stderr_text)
                           .find("sgmp-reference: the LIGGGHTS result still moves: its "
                                 "velocities give KE_trans/(m g d) = ") == 0u,
                   run.stderr_text);
        BOOST_TEST(!fs::exists(fake.out));
    }
    {  // two coincident spheres
        std::ofstream(dump) << settled_dump([&](std::vector<sgmp::Vec3>& c) { c[1] = c[0]; });
        const ProgramRun run = fake.pour({"--quiet"});
        BOOST_TEST(run.exit_code == 1);
        BOOST_TEST(first_line(run.stderr_text) ==
                   "sgmp-reference: the LIGGGHTS result has two spheres overlapping by 1 d; a "
                   "settled pour stays within 0.05 d");
        BOOST_TEST(!fs::exists(fake.out));
    }
}

BOOST_AUTO_TEST_CASE(sigkill_of_sgmp_reference_ends_liggghts_too) {
    // The fake records its own pid; with PR_SET_PDEATHSIG it dies with its parent.
    FakeLiggghts fake("");
    write_script(fake.dir / "bin" / "liggghts",
                 kBanner + "echo $$ > '" + (fake.dir / "liggghts.pid").string() + "'\ntouch '" +
                     (fake.dir / "started").string() + "'\nwhile true; do sleep 0.1; done\n");
    ProgramOptions options;
    options.args = {"pour", "--count", "150", "--seed", "1", "--out", fake.out.string(), "--quiet"};
    options.path = fake.path();
    options.signal_when_exists = fake.dir / "started";
    options.signal = SIGKILL;
    (void)run_program(kExe, options);
    BOOST_TEST(process_ended((fake.dir / "liggghts.pid").string()));
    BOOST_TEST(!fs::exists(fake.out));
}

BOOST_AUTO_TEST_CASE(work_directories_of_killed_runs_are_removed) {
    // A SIGKILLed sgmp-reference leaves its work directory in TMPDIR; the next pour removes
    // those whose process is gone (pid 4999999 is above Linux's largest) and keeps others.
    FakeLiggghts fake(kBanner + "exit 1\n");
    const fs::path tmp = fake.dir / "tmp";
    const fs::path orphan = tmp / "sgmp-reference-4999999-abcdef";
    const fs::path alive = tmp / ("sgmp-reference-" + std::to_string(::getpid()) + "-abcdef");
    fs::create_directories(orphan);
    fs::create_directories(alive);
    ::setenv("TMPDIR", tmp.c_str(), 1);
    const ProgramRun run = fake.pour({"--quiet"});
    ::unsetenv("TMPDIR");
    BOOST_TEST(run.exit_code == 1);
    BOOST_TEST(!fs::exists(orphan));
    BOOST_TEST(fs::exists(alive));
    BOOST_TEST(std::distance(fs::directory_iterator(tmp), fs::directory_iterator()) == 1);
}

BOOST_AUTO_TEST_CASE(values_once_accepted_silently_are_refused_with_the_prefix) {
    FakeLiggghts fake("");
    write_script(fake.dir / "bin" / "liggghts",
                 kBanner + "touch '" + (fake.dir / "ran").string() + "'\n");
    struct Case {
        std::string option, value, message;
    };
    const std::vector<Case> cases{
        {"--seed", "-1", "--seed -1: must be a whole number from 0 to 18446744073709551615"},
        {"--timeout", "nan", "--timeout: must be a number in [0, 2592000] s (30 days)"},
        {"--timeout", "-1", "--timeout: must be a number in [0, 2592000] s (30 days)"},
        {"--friction", "x", "--friction x: must be a number"},
        {"--density", "inf", "--density inf: must be positive"},
        {"--check-time", "1e-300", "--max-time 30: must be at most 10^6 settling checks"},
    };
    for (const auto& [option, value, message] : cases) {
        const ProgramRun run = fake.pour({option, value});
        BOOST_TEST(run.exit_code == 2, option << " " << value);
        BOOST_TEST(run.stderr_text.find("sgmp-reference: " + message) == 0u, run.stderr_text);
        BOOST_TEST(std::count(run.stderr_text.begin(), run.stderr_text.end(), '\n') == 1);
        BOOST_TEST(!fs::exists(fake.dir / "ran"));
    }
}

BOOST_AUTO_TEST_CASE(a_liggghts_error_is_shown_with_the_log_tail) {
    FakeLiggghts fake(kBanner +
                      "echo 'ERROR: Illegal fix wall/gran command (./src/fix_wall_gran.cpp:123)'\n"
                      "exit 1\n");
    const fs::path work = fake.dir / "work";
    const ProgramRun run = fake.pour({"--keep-work", work.string(), "--quiet"});
    BOOST_TEST(run.exit_code == 1);
    BOOST_TEST(first_line(run.stderr_text) ==
               "sgmp-reference: liggghts failed (exit code 1): ERROR: Illegal fix wall/gran "
               "command (./src/fix_wall_gran.cpp:123)");
    BOOST_TEST(run.stderr_text.find("--- last lines of its output ---") != std::string::npos);
    BOOST_TEST(!fs::exists(fake.out));
    BOOST_TEST(fs::exists(work / "in.pour"));  // kept for inspection
}

BOOST_AUTO_TEST_CASE(a_hanging_run_ends_at_the_timeout) {
    FakeLiggghts fake("");
    write_script(fake.dir / "bin" / "liggghts", hanging_fake(fake.dir, "echo SGMP-INSERTED 150\n"));
    const ProgramRun run = fake.pour({"--timeout", "1", "--quiet"});
    BOOST_TEST(run.exit_code == 1);
    BOOST_TEST(first_line(run.stderr_text) ==
               "sgmp-reference: timed out after 1 s (--timeout) at step 0: LIGGGHTS stopped, no "
               "pack written");
    BOOST_TEST(!fs::exists(fake.out));
    BOOST_TEST(process_ended((fake.dir / "sleep.pid").string()));
}

BOOST_AUTO_TEST_CASE(sigint_stops_the_child_and_leaves_no_file) {
    FakeLiggghts fake("");
    write_script(fake.dir / "bin" / "liggghts", hanging_fake(fake.dir));
    ProgramOptions options;
    options.args = {"pour", "--count", "150", "--seed", "1", "--out", fake.out.string(), "--quiet"};
    options.path = fake.path();
    options.signal_when_exists = fake.dir / "started";
    options.signal = SIGINT;
    const ProgramRun run = run_program(kExe, options);
    BOOST_TEST(run.exit_code == 130);
    BOOST_TEST(first_line(run.stderr_text) ==
               "sgmp-reference: interrupted at step 0: LIGGGHTS stopped, no pack written");
    BOOST_TEST(!fs::exists(fake.out));
    BOOST_TEST(process_ended((fake.dir / "sleep.pid").string()));
}

BOOST_AUTO_TEST_CASE(fewer_spheres_than_asked_stop_the_run) {
    FakeLiggghts fake("");
    write_script(fake.dir / "bin" / "liggghts", hanging_fake(fake.dir, "echo SGMP-INSERTED 140\n"));
    const ProgramRun run = fake.pour({"--timeout", "60", "--quiet"});
    BOOST_TEST(run.exit_code == 1);
    BOOST_TEST(first_line(run.stderr_text) ==
               "sgmp-reference: LIGGGHTS inserted only 140 of 150 spheres: the starting cloud is "
               "too dense, lower --cloud-fraction");
    BOOST_TEST(!fs::exists(fake.out));
}

BOOST_AUTO_TEST_CASE(an_unsettled_pour_is_an_error) {
    FakeLiggghts fake(kBanner +
                      "echo 'SGMP-PARAMETERS timestep 1e-4 rayleigh_time 1e-3 step_cap 1000'\n"
                      "echo 'SGMP-INSERTED 150'\necho 'SGMP-SETTLE 1000 0.02 1e-06'\n"
                      "echo 'SGMP-RESULT unsettled 1000 0.02'\necho SGMP-DONE\n");
    const ProgramRun run = fake.pour({"--quiet"});
    BOOST_TEST(run.exit_code == 1);
    BOOST_TEST(first_line(run.stderr_text) ==
               "sgmp-reference: not settled within the step cap of 1000 steps (30 s simulated): "
               "KE_trans/(m g d) = 0.02, threshold 1e-06");
    BOOST_TEST(!fs::exists(fake.out));
}

BOOST_AUTO_TEST_CASE(a_missing_liggghts_names_the_package) {
    FakeLiggghts fake("");
    ProgramOptions options;
    options.args = {"pour", "--count", "150", "--seed", "1", "--out", fake.out.string()};
    options.path = (fake.dir / "nothing-here").string();
    const ProgramRun run = run_program(kExe, options);
    BOOST_TEST(run.exit_code == 1);
    BOOST_TEST(first_line(run.stderr_text) ==
               "sgmp-reference: 'liggghts' not found on PATH: install the Debian package "
               "'liggghts'");
    BOOST_TEST(!fs::exists(fake.out));
}

BOOST_AUTO_TEST_CASE(a_missing_mpirun_names_the_package) {
    FakeLiggghts fake(kBanner);
    ProgramOptions options;
    options.args = {"pour",    "--count", "150",   "--seed",         "1",
                    "--ranks", "2",       "--out", fake.out.string()};
    options.path = (fake.dir / "bin").string();  // the fake liggghts and nothing else
    const ProgramRun run = run_program(kExe, options);
    BOOST_TEST(run.exit_code == 1);
    BOOST_TEST(first_line(run.stderr_text) ==
               "sgmp-reference: 'mpirun' not found on PATH (needed for --ranks 2): install the "
               "Debian package 'openmpi-bin'");
}

BOOST_AUTO_TEST_CASE(an_existing_output_is_kept_without_force) {
    FakeLiggghts fake(kBanner + "exit 1\n");
    { std::ofstream(fake.out) << "keep me\n"; }
    const ProgramRun run = fake.pour();
    BOOST_TEST(run.exit_code == 2);
    BOOST_TEST(run.stderr_text.find("--out") != std::string::npos);
    std::ifstream in(fake.out);
    std::string content;
    std::getline(in, content);
    BOOST_TEST(content == "keep me");
}

// Out of memory reading the start pack was "sgmp-reference: settle std::bad_alloc" with
// the usage status 2; it is the one message of every tool, status 1.
BOOST_AUTO_TEST_CASE(running_out_of_memory_is_one_line_and_status_1) {
    const fs::path dir = fresh_directory("sgmp-reference-oom");
    {
        std::ofstream big(dir / "big.xyz");
        constexpr int kCount = 1000000;  // about 60 MB of particles: past a 90 MB limit
        big << kCount << "\nProperties=id:I:1:pos:R:3:radius:R:1 pbc=\"F F F\"\n";
        for (int i = 0; i < kCount; ++i) {
            big << i + 1 << ' ' << (i % 100) * 0.01 << ' ' << (i / 100 % 100) * 0.01 << ' '
                << (i / 10000) * 0.01 << " 0.004\n";
        }
    }
    const sgmp::testing::CommandRun run = sgmp::testing::run_command(
        "ulimit -v 90000; OMP_NUM_THREADS=1 '" + kExe + "' settle '" + (dir / "big.xyz").string() +
            "' --friction 0.5 --out '" + (dir / "out.xyz").string() + "'",
        dir);
    BOOST_TEST(run.status == 1, run.err);
    BOOST_TEST(run.err.rfind("sgmp-reference: out of memory: ", 0) == 0u, run.err);
    BOOST_TEST(std::count(run.err.begin(), run.err.end(), '\n') == 1);
    BOOST_TEST(!fs::exists(dir / "out.xyz"));
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(usage_errors_exit_with_2) {
    FakeLiggghts fake(kBanner);
    BOOST_TEST(fake.pour({"--friction", "-1"}).exit_code == 2);
    BOOST_TEST(fake.pour({"--from-arrangement", "pyramid"}).exit_code == 2);
    BOOST_TEST(fake.pour({"--youngs-modulus", "1e6"}).exit_code == 2);
    ProgramOptions options;
    options.args = {"pour", "--count", "0", "--seed", "1", "--out", fake.out.string()};
    BOOST_TEST(run_program(kExe, options).exit_code == 2);
    BOOST_TEST(!fs::exists(fake.out));
}

BOOST_AUTO_TEST_CASE(help_documents_the_options) {
    ProgramOptions options;
    options.args = {"pour", "--help"};
    // CLI11 prints help on stdout; the exit code says it was help, not an error.
    BOOST_TEST(run_program(kExe, options).exit_code == 0);
    options.args = {"--version"};
    BOOST_TEST(run_program(kExe, options).exit_code == 0);
}

BOOST_AUTO_TEST_SUITE_END()

// --launcher: fake launchers (mpirun, Open MPI's mpirun, srun, a command line) that record
// their arguments and run the rest, so every launcher is tested where the real one is
// missing; --processors and the default grid in the input script.
BOOST_AUTO_TEST_SUITE(launchers)

namespace {

/// A launcher that writes its arguments to `log`, drops its own options and runs the rest.
std::string fake_launcher(const fs::path& log) {
    return "echo \"$*\" > '" + log.string() +
           "'\nwhile [ $# -gt 0 ]; do case \"$1\" in -np|-n|--ranks) shift 2 ;; "
           "--allow-run-as-root|--) shift ;; *) break ;; esac; done\nexec \"$@\"\n";
}

std::string slurp_text(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_launcher_runs_the_pour) {
    FakeLiggghts fake("");
    const fs::path dump = fake.dir / "result.dump";
    std::ofstream(dump) << settled_dump();
    write_script(fake.dir / "bin" / "liggghts", settled_fake(dump));
    const fs::path log = fake.dir / "launch.log";
    write_script(fake.dir / "bin" / "srun", fake_launcher(log));
    write_script(fake.dir / "bin" / "mpirun", fake_launcher(log));  // not Open MPI's
    write_script(fake.dir / "bin" / "mpirun.openmpi", fake_launcher(log));
    fs::create_symlink(fake.dir / "bin" / "mpirun.openmpi", fake.dir / "bin" / "orterun");
    write_script(fake.dir / "bin" / "launch-it", fake_launcher(log));
    const std::string root = ::geteuid() == 0 ? " --allow-run-as-root" : "";
    const struct {
        std::vector<std::string> args;
        std::string expected;  // the launcher's own arguments, before stdbuf/liggghts
        std::string grid;
    } cases[] = {
        {{"--ranks", "4"}, "-np 4 ", "2 1 2"},
        {{"--ranks", "2", "--launcher", "srun"}, "-n 2 ", "2 1 1"},
        {{"--ranks", "4", "--launcher", (fake.dir / "bin" / "orterun").string()},
         "-np 4" + root + " ",
         "2 1 2"},
        {{"--ranks", "3", "--launcher", "launch-it --ranks {np} --", "--processors", "1,1,3"},
         "--ranks 3 -- ",
         "1 1 3"},
    };
    for (const auto& c : cases) {
        std::vector<std::string> args{"--quiet", "--force", "--keep-work",
                                      (fake.dir / "work").string()};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const ProgramRun run = fake.pour(args);
        BOOST_TEST(run.exit_code == 0, run.stderr_text);
        const std::string launched = slurp_text(log);
        BOOST_TEST(launched.rfind(c.expected, 0) == 0u, launched);
        BOOST_TEST(launched.find("liggghts -in in.pour") != std::string::npos, launched);
        BOOST_TEST(slurp_text(fake.dir / "work" / "in.pour").find("processors      " + c.grid) !=
                       std::string::npos,
                   c.grid);
        fs::remove(log);
        fs::remove_all(fake.dir / "work");
    }
    // A launcher that refuses to start LIGGGHTS (as Open MPI's does as root) is named, with
    // its first line that says something (not the banner of dashes).
    write_script(fake.dir / "bin" / "refuse",
                 "#!/bin/sh\necho '-------------'\necho 'refuse has detected an attempt to "
                 "run as root.'\necho 'Running as root is *strongly* discouraged.'\n"
                 "echo '-------------'\nexit 1\n");
    fs::remove(fake.out);  // the cases above wrote it
    const ProgramRun refused =
        fake.pour({"--quiet", "--force", "--ranks", "2", "--launcher", "refuse -n {np}"});
    BOOST_TEST(refused.exit_code == 1);
    BOOST_TEST(first_line(refused.stderr_text) ==
                   "sgmp-reference: the launcher 'refuse -n {np}' (--launcher) failed (exit code "
                   "1): refuse has detected an attempt to run as root.",
               refused.stderr_text);
    BOOST_TEST(!fs::exists(fake.out));
    // Bad launcher and grid: one line each, nothing written.
    const ProgramRun no_np =
        fake.pour({"--quiet", "--force", "--ranks", "2", "--launcher", "launch-it -n 2"});
    BOOST_TEST(no_np.exit_code != 0);
    BOOST_TEST(first_line(no_np.stderr_text).find("must hold {np}") != std::string::npos,
               no_np.stderr_text);
    const ProgramRun bad_grid =
        fake.pour({"--quiet", "--force", "--ranks", "2", "--processors", "2,2,1"});
    BOOST_TEST(bad_grid.exit_code == 2);
    BOOST_TEST(first_line(bad_grid.stderr_text).find("--processors 2,2,1: must be PX,PY,PZ") !=
                   std::string::npos,
               bad_grid.stderr_text);
}

BOOST_AUTO_TEST_SUITE_END()
