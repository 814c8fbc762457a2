// What an output may touch: --force replaces only what the command writes, temporaries and
// locks never follow a symbolic link, and every stop signal removes the temporaries.

#include <sys/wait.h>
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <csignal>
#include <set>
#include <stdexcept>
#include <string>

#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/host_name.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "sgmp/pack/output_lock.hpp"
#include "test_support.hpp"

using namespace sgmp;
using namespace sgmp::testing;
namespace fs = std::filesystem;

namespace {

/// The name a writer of this process gives the temporary of `target`.
fs::path temporary_of(const fs::path& target, const char* kind = "tmp") {
    return target.parent_path() / ("." + target.filename().string() + "." + kind + "-" +
                                   std::to_string(::getpid()) + "." + host_name());
}

/// Writes the outputs `names` (files, "sub/file" in subdirectories) into a directory.
void write_outputs(const fs::path& target, bool overwrite, const std::set<std::string>& names) {
    write_directory_atomically(target, overwrite, [&](const fs::path& directory) {
        for (const std::string& name : names) {
            fs::create_directories((directory / name).parent_path());
            write_text_file(directory / name, "new " + name);
        }
    });
}

std::string message_of(const std::function<void()>& work) {
    try {
        work();
    } catch (const std::exception& error) {
        return error.what();
    }
    return "no error";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(output_safety)

// `sgmp-compare measure p1.xyz --out "$PWD" --force` deleted the whole current directory.
BOOST_AUTO_TEST_CASE(force_never_deletes_a_directory_holding_anything_else) {
    TestDirectory scratch("safety_force");
    const fs::path out = scratch.path() / "out";
    fs::create_directories(out / "sub");
    write_text(out / "p1.xyz", "precious");
    write_text(out / "sub" / "notes.txt", "mine");
    const std::string refusal = message_of([&] { write_outputs(out, true, {"m.json"}); });
    BOOST_TEST(refusal.find("which this command did not write") != std::string::npos, refusal);
    BOOST_TEST(read_bytes(out / "p1.xyz") == "precious");
    BOOST_TEST(read_bytes(out / "sub" / "notes.txt") == "mine");
    BOOST_TEST(!fs::exists(out / "m.json"));
    BOOST_TEST(std::distance(fs::directory_iterator(scratch.path()), fs::directory_iterator()) ==
               1);
}

BOOST_AUTO_TEST_CASE(force_replaces_the_outputs_it_wrote_before) {
    TestDirectory scratch("safety_rewrite");
    const fs::path out = scratch.path() / "report";
    write_outputs(out, false, {"a.csv", "plots/n150.svg", "plots/n300.svg"});
    BOOST_TEST(fs::is_regular_file(out / kOutputRecord));
    // A smaller set replaces the larger one: the record names the old outputs.
    write_outputs(out, true, {"a.csv", "plots/n150.svg"});
    BOOST_TEST(read_bytes(out / "a.csv") == "new a.csv");
    BOOST_TEST(!fs::exists(out / "plots" / "n300.svg"));
    // Something the user put in afterwards is never deleted.
    write_text(out / "plots" / "mine.svg", "x");
    BOOST_CHECK_THROW(write_outputs(out, true, {"a.csv"}), std::runtime_error);
    BOOST_TEST(fs::exists(out / "plots" / "mine.svg"));
    // A directory without a record (an older version's) is replaced when the new outputs
    // name all it holds.
    const fs::path legacy = scratch.path() / "legacy";
    fs::create_directories(legacy);
    write_text(legacy / "a.csv", "old");
    write_outputs(legacy, true, {"a.csv", "b.csv"});
    BOOST_TEST(read_bytes(legacy / "a.csv") == "new a.csv");
}

BOOST_AUTO_TEST_CASE(force_refuses_links_files_and_the_current_directory) {
    TestDirectory scratch("safety_kinds");
    const fs::path victim = scratch.path() / "victim";
    fs::create_directories(victim);
    fs::create_directory_symlink(victim, scratch.path() / "link");
    std::string refusal =
        message_of([&] { write_outputs(scratch.path() / "link", true, {"a.csv"}); });
    BOOST_TEST(refusal.find("symbolic link") != std::string::npos, refusal);
    write_text(scratch.path() / "p1.xyz", "precious");
    refusal = message_of([&] { write_outputs(scratch.path() / "p1.xyz", true, {"a.csv"}); });
    BOOST_TEST(refusal.find("not a directory") != std::string::npos, refusal);
    BOOST_TEST(read_bytes(scratch.path() / "p1.xyz") == "precious");

    // The current directory (even an empty one) and its ancestors, spelled any way.
    const fs::path empty = scratch.path() / "empty";
    fs::create_directories(empty);
    const fs::path here = fs::current_path();
    fs::current_path(empty);
    for (const fs::path& spelling : {fs::path("."), empty, empty.parent_path()}) {
        refusal = message_of([&] { write_outputs(spelling, true, {"a.csv"}); });
        BOOST_TEST(refusal.find("current directory") != std::string::npos, refusal);
    }
    fs::current_path(here);
    BOOST_TEST(fs::is_directory(empty));
    BOOST_TEST(fs::is_empty(empty));
}

// A link planted at a temporary's name made `sgmp pack --out o.xyz` overwrite its target.
BOOST_AUTO_TEST_CASE(temporaries_never_follow_a_planted_link) {
    TestDirectory scratch("safety_temporary");
    const fs::path victim = scratch.path() / "victim.txt";
    write_text(victim, "precious");
    const fs::path target = scratch.path() / "o.xyz";
    fs::create_symlink(victim, temporary_of(target));
    write_file_atomically(target, false, [](std::ostream& out) { out << "pack"; });
    BOOST_TEST(read_bytes(victim) == "precious");
    BOOST_TEST(!fs::is_symlink(target));
    BOOST_TEST(read_bytes(target) == "pack");

    const fs::path victim_directory = scratch.path() / "victim-dir";
    fs::create_directories(victim_directory);
    const fs::path report = scratch.path() / "report";
    fs::create_directory_symlink(victim_directory, temporary_of(report));
    write_outputs(report, false, {"a.csv"});
    BOOST_TEST(fs::is_empty(victim_directory));
    BOOST_TEST(!fs::is_symlink(report));
    BOOST_TEST(read_bytes(report / "a.csv") == "new a.csv");
}

// `ln -s victim.txt .summary.csv.lock` had the holder's line written into victim.txt.
BOOST_AUTO_TEST_CASE(a_lock_never_follows_a_planted_link) {
    TestDirectory scratch("safety_lock");
    const fs::path victim = scratch.path() / "victim.txt";
    write_text(victim, "precious");
    fs::create_symlink(victim, scratch.path() / ".summary.csv.lock");
    const std::string refusal =
        message_of([&] { const OutputLock lock(scratch.path() / "summary.csv"); });
    BOOST_TEST(refusal.find("is a symbolic link") != std::string::npos, refusal);
    BOOST_TEST(read_bytes(victim) == "precious");
}

// A closed terminal (SIGHUP) or Ctrl-\ (SIGQUIT) left `.tmp-PID.HOST` files of 6 MB.
BOOST_AUTO_TEST_CASE(every_stop_signal_removes_the_temporaries_and_exits_130) {
    TestDirectory scratch("safety_signals");
    for (const int number : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
        const pid_t pid = ::fork();
        BOOST_TEST_REQUIRE(pid >= 0);
        if (pid == 0) {
            ::alarm(20);
            install_interrupt_handler("pack_tests");
            write_file_atomically(scratch.path() / "big.xyz", false, [&](std::ostream& out) {
                out << std::string(1 << 20, 'x');
                ::kill(::getpid(), number);
                ::pause();  // the watcher thread exits the process
            });
            ::_exit(0);
        }
        int raw = 0;
        ::waitpid(pid, &raw, 0);
        BOOST_TEST_INFO("signal " << number);
        BOOST_TEST((WIFEXITED(raw) ? WEXITSTATUS(raw) : -1) == 130);
        BOOST_TEST(fs::is_empty(scratch.path()));
    }
}

BOOST_AUTO_TEST_SUITE_END()
