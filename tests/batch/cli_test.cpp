// `sgmp batch` end to end: bad input, refusal to overwrite, resuming, in-process packs equal
// to `sgmp pack`'s, MPI ranks and shards equal to the serial run.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "sgmp/batch/summary.hpp"
#include "sgmp/metrics/summary_columns.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace sgmp::batch;

namespace {

using Run = sgmp::testing::CommandRun;

/// The schema `sgmp batch` writes: sgmp-compare's metric columns.
const SummarySchema& schema() {
    static const SummarySchema s(sgmp::metrics::summary_column_names());
    return s;
}

struct Scratch {
    sgmp::testing::TestDirectory scratch{
        "batch-cli-" + boost::unit_test::framework::current_test_case().p_name.get()};
    const fs::path& dir = scratch.path();
    Scratch() { fs::create_directories(dir / "io"); }
    [[nodiscard]] fs::path path(const std::string& name) const { return dir / name; }

    /// Runs `prefix sgmp batch ARGS` in `cwd` (relative to the scratch directory), its
    /// output captured in the files stdout and stderr of the scratch directory.
    [[nodiscard]] Run batch(const std::string& args, const std::string& cwd = "io",
                            const std::string& prefix = "") const {
        fs::create_directories(dir / cwd);
        return sgmp::testing::run_command("cd '" + (dir / cwd).string() + "' && " + prefix + " '" +
                                              SGMP_EXECUTABLE + "' batch " + args,
                                          dir);
    }

    /// Every file under `cwd`, relative paths, sorted.
    [[nodiscard]] std::vector<std::string> files(const std::string& cwd = "io") const {
        std::vector<std::string> names;
        for (const auto& entry : fs::recursive_directory_iterator(dir / cwd)) {
            if (entry.is_regular_file()) {
                names.push_back(fs::relative(entry.path(), dir / cwd).string());
            }
        }
        std::sort(names.begin(), names.end());
        return names;
    }
};

/// The summary without its timing columns (seconds, measure_seconds), one string per row.
std::vector<std::string> untimed(const fs::path& summary) {
    const SummaryTable table = schema().parse(sgmp::testing::read_bytes(summary), summary.string());
    const auto header = schema().header();
    std::vector<std::string> rows;
    for (const auto& row : table.rows) {
        std::string text;
        for (std::size_t i = 0; i < header.size(); ++i) {
            if (header[i] != "seconds" && header[i] != "measure_seconds") {
                text += row.fields[i] + ",";
            }
        }
        rows.push_back(text);
    }
    return rows;
}

const std::string kSweep =
    "--seeds 1-3 --count 60,120 --arrangement loose-random,small-dense --gap largest,random "
    "--out-pattern 'packs/{arrangement}/n{count}-{gap}-s{seed}.xyz.gz' --progress-seconds 0";

void expect_same_packs(const Scratch& s, const std::string& a, const std::string& b) {
    const auto names = s.files(a);
    BOOST_TEST(names == s.files(b));
    for (const std::string& name : names) {
        if (name.rfind("packs/", 0) == 0) {
            BOOST_TEST(sgmp::testing::read_bytes(s.path(a) / name) ==
                           sgmp::testing::read_bytes(s.path(b) / name),
                       name);
        }
    }
}

}  // namespace

BOOST_AUTO_TEST_CASE(bad_input_gets_one_line_and_writes_nothing) {
    Scratch s;
    std::ofstream(s.path("io/file")) << "x";
    const std::string base = "--count 50 --arrangement small-dense --out-pattern 'p/{seed}.xyz' ";
    const struct {
        std::string args;
        int status;
        std::string message;
    } cases[] = {
        {base + "--seeds 5-1", 2, "sgmp: --seeds 5-1: range 5-1 runs backwards"},
        {base + "--seeds x", 2, "sgmp: --seeds x: must be seeds S or ranges A-B"},
        {"--seeds 1 --count 50 --out-pattern p.xyz", 2,
         "sgmp: --arrangement: the grid is empty; give at least one value"},
        {base + "--seeds 1-4 --shard 5/4", 2, "sgmp: --shard 5/4: I must lie in 1..4"},
        {base + "--seeds 1-4 --shard 0/4", 2, "sgmp: --shard 0/4: I must lie in 1..4"},
        {base + "--seeds 1 --count 0", 2, "sgmp: --count 0: must be between 1 and 10000000"},
        {base + "--seeds 1 --summary file/summary.csv", 1,
         "sgmp: --summary file/summary.csv: cannot create its directory file"},
        {"--seeds 1 --count 50 --arrangement small-dense --out-pattern 'file/p/{seed}.xyz'", 1,
         "sgmp: file/p/1.xyz: cannot be written (file is not a directory)"},
        {"--seeds 1-2 --count 50 --arrangement small-dense --out-pattern p.xyz", 2,
         "sgmp: --out-pattern p.xyz: must hold {seed}"},
        {base + "--seeds 1", 2, "sgmp: --seeds: needed"},
        // 10^8 jobs: refused at once (it used to plan past 10 GB), with the shards to use.
        {"--seeds 1-10000000 --count 10,20,30,40,50,60,70,80,90,100 --arrangement small-dense "
         "--no-packs",
         2,
         "sgmp: the grid holds 100000000 jobs (100000000 in this shard); one batch runs at most "
         "1000000: split it with --shard I/100 or more shards"},
    };
    for (const auto& c : cases) {
        const std::string args = c.args == base + "--seeds 1"
                                     ? "--count 50 --arrangement small-dense --out-pattern p.xyz"
                                     : c.args;
        const Run r = s.batch(args);
        BOOST_TEST(r.status == c.status, args);
        BOOST_TEST(r.err.rfind(c.message, 0) == 0u, args + " -> " + r.err);
        BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, r.err);
        BOOST_TEST(s.files() == std::vector<std::string>{"file"}, args);
    }
}

BOOST_AUTO_TEST_CASE(batch_packs_equal_sgmp_pack_and_reruns_are_refused) {
    Scratch s;
    const std::string args =
        "--seeds 4,2 --count 80 --arrangement large-dense --relax none,frictionless "
        "--out-pattern 'p/{relax}-{seed}.xyz' --progress-seconds 0";
    BOOST_REQUIRE(s.batch(args).status == 0);
    const std::string pack = std::string("cd '") + s.path("io").string() + "' && '" +
                             SGMP_EXECUTABLE +
                             "' pack --count 80 --arrangement large-dense --relax frictionless "
                             "--keep-uncertified --seed 2 --out single.xyz >/dev/null";
    BOOST_REQUIRE(std::system(pack.c_str()) == 0);
    BOOST_TEST(sgmp::testing::read_bytes(s.path("io/single.xyz")) ==
               sgmp::testing::read_bytes(s.path("io/p/frictionless-2.xyz")));
    // Row order: relax none before frictionless, seeds as listed.
    const auto rows =
        schema().parse(sgmp::testing::read_bytes(s.path("io/summary.csv")), "summary").rows;
    BOOST_REQUIRE(rows.size() == 4u);
    BOOST_TEST(rows[1].fields.back() == "p/none-2.xyz");
    BOOST_TEST(rows[2].fields.back() == "p/frictionless-4.xyz");
    // Defaults that depend on the job (the relaxation's schedule by mode, the sweep stages by
    // arrangement), unswept: the values the pack ran, as its header records them; blank where
    // nothing relaxed.
    const auto field = [&](std::size_t row, std::string_view name) {
        return rows[row].fields.at(1 + parameter_index(name));
    };
    BOOST_TEST(field(1, "relax_stiffness") == "");
    BOOST_TEST(field(2, "relax_stiffness") == "20000");
    BOOST_TEST(field(2, "relax_stages") == "1");
    BOOST_TEST(field(2, "relax_time") == "200");
    BOOST_TEST(field(1, "sweep_stages") == "120");  // large-dense's stages, unswept
    // A re-run: exit 1 naming the first existing file; nothing changes.
    const auto before = sgmp::testing::read_bytes(s.path("io/summary.csv"));
    const Run again = s.batch(args);
    BOOST_TEST(again.status == 1);
    BOOST_TEST(again.err ==
               "sgmp: summary.csv: exists; pass --skip-existing to keep what is "
               "there or --force to remake it\n");
    fs::rename(s.path("io/summary.csv"), s.path("old.csv"));
    const Run packs_exist = s.batch(args);
    BOOST_TEST(packs_exist.status == 1);
    BOOST_TEST(packs_exist.err.rfind("sgmp: p/none-4.xyz: exists;", 0) == 0u);
    BOOST_TEST(!fs::exists(s.path("io/summary.csv")));
    BOOST_TEST(s.batch(args + " --force").status == 0);
    BOOST_TEST(sgmp::testing::read_bytes(s.path("io/single.xyz")) ==
               sgmp::testing::read_bytes(s.path("io/p/frictionless-2.xyz")));
    BOOST_TEST(untimed(s.path("io/summary.csv")) == untimed(s.path("old.csv")));
    (void)before;
}

// A size-distribution file and a lognormal spec in one grid: each batch pack has the bytes
// of `sgmp pack` with the same distribution; an unreadable or malformed file is refused in
// one line before any pack is made.
BOOST_AUTO_TEST_CASE(size_distributions_from_files_and_specs) {
    Scratch s;
    sgmp::testing::write_text(s.path("io/blend.csv"), "diameter,fraction\n1,0.5\n0.5,0.5\n");
    sgmp::testing::write_text(s.path("io/bad.csv"), "diameter,fraction\n1,-1\n");
    const std::string grid =
        "--seeds 3 --count 400 --arrangement loose-random --fraction-basis volume "
        "--out-pattern 'p/{size_distribution}.xyz' --progress-seconds 0 --size-distribution ";
    BOOST_REQUIRE(s.batch(grid + "blend.csv,lognormal:2:0.4:3").status == 0);
    for (const std::string distribution : {"blend.csv", "lognormal:2:0.4:3"}) {
        const std::string pack =
            std::string("cd '") + s.path("io").string() + "' && '" + SGMP_EXECUTABLE +
            "' pack --count 400 --arrangement loose-random --fraction-basis volume --seed 3 "
            "--size-distribution " +
            distribution + " --out single.xyz --force >/dev/null";
        BOOST_REQUIRE(std::system(pack.c_str()) == 0);
        BOOST_TEST(sgmp::testing::read_bytes(s.path("io/single.xyz")) ==
                       sgmp::testing::read_bytes(s.path("io/p/" + distribution + ".xyz")),
                   distribution);
    }
    const Run missing = s.batch(grid + "nowhere.csv --summary m.csv");
    BOOST_TEST(missing.status == 2);
    BOOST_TEST(missing.err.rfind("sgmp: --size-distribution nowhere.csv: must name a readable "
                                 "file",
                                 0) == 0u);
    const Run bad = s.batch(grid + "bad.csv --summary b.csv");
    BOOST_TEST(bad.status == 2);
    BOOST_TEST(bad.err.rfind("sgmp: --size-distribution bad.csv:2:", 0) == 0u, bad.err);
    BOOST_TEST(std::count(bad.err.begin(), bad.err.end(), '\n') == 1);
    BOOST_TEST(!fs::exists(s.path("io/m.csv")));
    BOOST_TEST(!fs::exists(s.path("io/b.csv")));
}

BOOST_AUTO_TEST_CASE(config_file_lists_equal_the_command_line) {
    Scratch s;
    std::ofstream(s.path("io/sweep.toml"))
        << "seeds = \"1-2\"\ncount = [60, 90]\narrangement = \"small-dense\"\n"
           "out-pattern = \"packs/n{count}-s{seed}.xyz\"\nprogress-seconds = 0\n";
    BOOST_REQUIRE(s.batch("--config sweep.toml --no-packs --summary c.csv").status == 0);
    BOOST_REQUIRE(s.batch("--seeds 1-2 --count 60 --count 90 --arrangement small-dense "
                          "--no-packs --summary l.csv --progress-seconds 0")
                      .status == 0);
    BOOST_TEST(untimed(s.path("io/c.csv")) == untimed(s.path("io/l.csv")));
    BOOST_TEST(untimed(s.path("io/c.csv")).size() == 4u);
    BOOST_TEST(s.files() == (std::vector<std::string>{"c.csv", "l.csv", "sweep.toml"}));
    // A list on the command line replaces the file's (they added up: 3 counts, 6 packs).
    BOOST_REQUIRE(s.batch("--config sweep.toml --count 60 --no-packs --summary o.csv").status == 0);
    BOOST_REQUIRE(s.batch("--seeds 1-2 --count 60 --arrangement small-dense --no-packs "
                          "--summary m.csv --progress-seconds 0")
                      .status == 0);
    BOOST_TEST(untimed(s.path("io/o.csv")) == untimed(s.path("io/m.csv")));
    BOOST_TEST(untimed(s.path("io/o.csv")).size() == 2u);
}

BOOST_AUTO_TEST_CASE(measured_rows_and_progress_lines) {
    Scratch s;
    const Run r = s.batch(
        "--seeds 1-2 --count 150 --arrangement loose-random --no-packs --measure "
        "--progress-seconds 0.01");
    BOOST_REQUIRE(r.status == 0);
    // stderr is a file here, not a terminal: progress lines still come.
    BOOST_TEST(r.err.find("sgmp batch: ") != std::string::npos, r.err);
    BOOST_TEST(r.err.find(" / 2 packs") != std::string::npos);
    const SummaryTable t =
        schema().parse(sgmp::testing::read_bytes(s.path("io/summary.csv")), "summary");
    BOOST_REQUIRE(t.rows.size() == 2u);
    const auto header = schema().header();
    const auto at = [&](std::size_t row, const std::string& name) {
        return t.rows[row].fields[std::find(header.begin(), header.end(), name) - header.begin()];
    };
    for (std::size_t i = 0; i < 2; ++i) {
        // Loose-random packs of equal spheres: phi of the control volume well inside (0.5,
        // 0.65) (thesis Table 6.1: about 0.58), Z at the widest tolerance at least that
        // at contact, no overlaps (the protocol never overlaps by more than 1e-9 d).
        BOOST_TEST(std::stod(at(i, "phi")) > 0.5);
        BOOST_TEST(std::stod(at(i, "phi")) < 0.65);
        BOOST_TEST(std::stod(at(i, "z_5e-2")) >= std::stod(at(i, "z_0")));
        BOOST_TEST(at(i, "overlaps") == "0");
        BOOST_TEST(!at(i, "split_ratio").empty());
        BOOST_TEST(at(i, "voronoi_phi_mean").empty());
        BOOST_TEST(at(i, "path").empty());
    }
}

BOOST_AUTO_TEST_CASE(resumed_batches_end_with_the_uninterrupted_table) {
    Scratch s;
    BOOST_REQUIRE(s.batch(kSweep + " --measure", "whole").status == 0);
    // A batch stopped half way (its first shard done), then resumed.
    BOOST_REQUIRE(
        s.batch(kSweep + " --measure --shard 1/2 --summary partial.csv", "resumed").status == 0);
    fs::remove(s.path("resumed/partial.csv"));
    const Run resumed = s.batch(kSweep + " --measure --skip-existing", "resumed");
    BOOST_REQUIRE(resumed.status == 0);
    BOOST_TEST(resumed.out.find("(12 reused)") != std::string::npos, resumed.out);
    BOOST_TEST(untimed(s.path("resumed/summary.csv")) == untimed(s.path("whole/summary.csv")));
    expect_same_packs(s, "whole", "resumed");

    // A real interruption: SIGTERM during the batch, exit 130, no temporary left.
    const std::string big =
        "--seeds 1-400 --count 400 --arrangement loose-random "
        "--out-pattern 'packs/s{seed}.xyz' --threads 1 --progress-seconds 0";
    fs::create_directories(s.path("stopped"));
    const pid_t child = ::fork();
    if (child == 0) {
        ::chdir(s.path("stopped").c_str());
        ::execl(
            "/bin/sh", "sh", "-c",
            ("exec '" + std::string(SGMP_EXECUTABLE) + "' batch " + big + " 2>/dev/null").c_str(),
            static_cast<char*>(nullptr));
        ::_exit(127);
    }
    for (int i = 0; i < 400 && !fs::exists(s.path("stopped/packs/s3.xyz")); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(25));
    }
    ::kill(child, SIGTERM);
    int raw = 0;
    ::waitpid(child, &raw, 0);
    BOOST_TEST((WIFEXITED(raw) ? WEXITSTATUS(raw) : -1) == 130);
    for (const std::string& name : s.files("stopped")) {
        BOOST_TEST(name.find(".tmp-") == std::string::npos, name);
    }
    BOOST_TEST(!fs::exists(s.path("stopped/summary.csv")));
    const std::size_t made = s.files("stopped").size();
    BOOST_TEST(made < 400u);
    BOOST_REQUIRE(s.batch(big + " --skip-existing", "stopped").status == 0);
    // The uninterrupted table of the first 40 seeds equals the resumed one's first rows.
    BOOST_REQUIRE(s.batch("--seeds 1-400 --count 400 --arrangement loose-random --no-packs "
                          "--progress-seconds 0",
                          "straight")
                      .status == 0);
    auto resumed_rows = untimed(s.path("stopped/summary.csv"));
    auto straight_rows = untimed(s.path("straight/summary.csv"));
    BOOST_REQUIRE(resumed_rows.size() == straight_rows.size());
    for (std::size_t i = 0; i < resumed_rows.size(); ++i) {
        // The paths differ (--no-packs): compare everything before them.
        BOOST_TEST(
            resumed_rows[i].substr(0, resumed_rows[i].rfind(',', resumed_rows[i].size() - 2)) ==
            straight_rows[i].substr(0, straight_rows[i].rfind(',', straight_rows[i].size() - 2)));
    }
}

BOOST_AUTO_TEST_CASE(shards_merged_equal_the_serial_run) {
    Scratch s;
    BOOST_REQUIRE(s.batch(kSweep, "serial").status == 0);
    for (int i = 1; i <= 3; ++i) {
        BOOST_REQUIRE(s.batch(kSweep + " --shard " + std::to_string(i) + "/3 --summary shard-" +
                                  std::to_string(i) + ".csv",
                              "sharded")
                          .status == 0);
    }
    const Run merge =
        s.batch("--merge shard-3.csv shard-1.csv shard-2.csv --summary summary.csv", "sharded");
    BOOST_REQUIRE(merge.status == 0);
    BOOST_TEST(untimed(s.path("sharded/summary.csv")) == untimed(s.path("serial/summary.csv")));
    for (int i = 1; i <= 3; ++i) {
        fs::remove(s.path("sharded/shard-" + std::to_string(i) + ".csv"));
    }
    expect_same_packs(s, "serial", "sharded");
    BOOST_TEST(s.batch("--merge shard-1.csv --summary summary.csv", "sharded").status == 1);
}

BOOST_AUTO_TEST_CASE(mpi_ranks_equal_the_serial_run) {
    Scratch s;
    BOOST_REQUIRE(s.batch(kSweep + " --measure", "serial").status == 0);
    const std::string mpirun = std::string("'") + MPIEXEC + "'" +
                               (::geteuid() == 0 ? " --allow-run-as-root" : "") +
                               " --oversubscribe -np 2";
    const Run r = s.batch(kSweep + " --measure", "mpi", mpirun);
    BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
    BOOST_TEST(r.out.find("on 2 rank(s)") != std::string::npos, r.out);
    expect_same_packs(s, "serial", "mpi");
    BOOST_TEST(untimed(s.path("mpi/summary.csv")) == untimed(s.path("serial/summary.csv")));
    // Resumed on 2 ranks, every pack is reused, and the count says so for all ranks.
    const Run again = s.batch(kSweep + " --measure --skip-existing", "mpi", mpirun);
    BOOST_REQUIRE_MESSAGE(again.status == 0, again.err);
    const auto packs = again.out.find("batch of ");
    BOOST_REQUIRE(packs != std::string::npos);
    const std::string total =
        again.out.substr(packs + 9, again.out.find(' ', packs + 9) - packs - 9);
    BOOST_TEST(again.out.find("(" + total + " reused)") != std::string::npos, again.out);
}

namespace {

std::string host_name() {
    char host[256] = {};
    ::gethostname(host, sizeof host - 1);
    return host;
}

/// The id of a process that has ended (started and waited for).
pid_t ended_process() {
    const pid_t child = ::fork();
    if (child == 0) {
        ::_exit(0);
    }
    ::waitpid(child, nullptr, 0);
    return child;
}

}  // namespace

// Once, a second batch naming the same summary overwrote the first's rows when it finished
// last; now it is refused at its start while the first runs (and the first is untouched).
BOOST_AUTO_TEST_CASE(a_second_batch_on_one_summary_is_refused_while_the_first_runs) {
    Scratch s;
    fs::create_directories(s.path("io"));
    const pid_t first = ::fork();
    if (first == 0) {
        ::chdir(s.path("io").c_str());
        ::execl("/bin/sh", "sh", "-c",
                ("exec '" + std::string(SGMP_EXECUTABLE) +
                 "' batch --seeds 1-400 --count 400 --arrangement loose-random --out-pattern "
                 "'a/s{seed}.xyz' --threads 1 "
                 "--progress-seconds 0 >/dev/null 2>&1")
                    .c_str(),
                static_cast<char*>(nullptr));
        ::_exit(127);
    }
    for (int i = 0; i < 400 && !fs::exists(s.path("io/a/s2.xyz")); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(25));
    }
    BOOST_REQUIRE(fs::exists(s.path("io/.summary.csv.lock")));
    const Run second =
        s.batch("--seeds 1-3 --count 60 --arrangement loose-random --out-pattern 'b/s{seed}.xyz'");
    BOOST_TEST(second.status == 1);
    BOOST_TEST(second.err.find("sgmp: --summary summary.csv: is being written by another "
                               "process (" +
                               host_name() + " pid " + std::to_string(first) + ")") == 0,
               second.err);
    BOOST_TEST(std::count(second.err.begin(), second.err.end(), '\n') == 1);
    BOOST_TEST(!fs::exists(s.path("io/b")));
    ::kill(first, SIGTERM);
    int raw = 0;
    ::waitpid(first, &raw, 0);
    BOOST_TEST((WIFEXITED(raw) ? WEXITSTATUS(raw) : -1) == 130);
    BOOST_TEST(!fs::exists(s.path("io/.summary.csv.lock")));  // released with its holder
    BOOST_TEST(
        s.batch("--seeds 1-3 --count 60 --arrangement loose-random --out-pattern 'b/s{seed}.xyz'")
            .status == 0);
    BOOST_TEST(!fs::exists(s.path("io/.summary.csv.lock")));
}

// A batch whose job fails stops through World::abort (std::exit, MPI_Abort), which skips
// the summary lock's destructor: .SUMMARY.lock was left behind.
BOOST_AUTO_TEST_CASE(a_failed_job_leaves_no_summary_lock) {
    Scratch s;
    const Run r = s.batch(
        "--seeds 1-3 --count 2000 --arrangement small-dense --out-pattern 'p{seed}.xyz' "
        "--threads 1 --progress-seconds 0",
        "io", "ulimit -f 2;");  // each pack is larger than 2 kB: its write fails
    BOOST_TEST(r.status == 1, r.err);
    BOOST_TEST(r.err.find("File too large") != std::string::npos, r.err);
    BOOST_TEST(!fs::exists(s.path("io/.summary.csv.lock")));
    BOOST_TEST(s.files().empty());  // no pack, no temporary, no lock
}

// Once, of two --skip-existing batches making the same packs side by side, one failed with
// "exists; pass --force" when the other published a pack first; now that pack is reused.
BOOST_AUTO_TEST_CASE(concurrent_resumes_of_the_same_packs_both_finish) {
    Scratch s;
    const std::string sweep =
        "--seeds 1-40 --count 60 --arrangement loose-random --out-pattern 'packs/s{seed}.xyz' "
        "--threads 1 "
        "--progress-seconds 0 --skip-existing";
    const Run both = sgmp::testing::run_command(
        "cd '" + s.path("io").string() + "' && { '" + SGMP_EXECUTABLE + "' batch " + sweep +
            " --summary a.csv 2>a.err & '" + SGMP_EXECUTABLE + "' batch " + sweep +
            " --summary b.csv 2>b.err & wait %1; echo $? >a.status; wait %2; echo $? >b.status; }",
        s.dir);
    BOOST_REQUIRE(both.status == 0);
    BOOST_TEST(sgmp::testing::read_bytes(s.path("io/a.status")) == "0\n",
               sgmp::testing::read_bytes(s.path("io/a.err")));
    BOOST_TEST(sgmp::testing::read_bytes(s.path("io/b.status")) == "0\n",
               sgmp::testing::read_bytes(s.path("io/b.err")));
    BOOST_TEST(untimed(s.path("io/a.csv")) == untimed(s.path("io/b.csv")));
    BOOST_TEST(untimed(s.path("io/a.csv")).size() == 40u);
    for (const std::string& name : s.files()) {
        BOOST_TEST(name.find(".tmp-") == std::string::npos, name);
    }
}

// Once, a temporary that a SIGKILLed batch left was never removed by its resume.
BOOST_AUTO_TEST_CASE(a_resume_removes_the_temporaries_of_killed_writers_only) {
    Scratch s;
    fs::create_directories(s.path("io/packs"));
    const std::string host = host_name();
    const std::string dead = std::to_string(ended_process());
    const std::string alive = std::to_string(::getpid());
    const auto make = [&](const std::string& name, bool directory) {
        if (directory) {
            fs::create_directories(s.path("io/packs") / name / "inner");
        } else {
            std::ofstream(s.path("io/packs") / name) << "half a pack";
        }
    };
    make(".s1.xyz.tmp-" + dead + "." + host, false);       // killed here: removed
    make(".s2.xyz.tmp-" + dead + "." + host, true);        // a killed directory write: removed
    make(".s3.xyz.tmp-" + alive + "." + host, false);      // still being written: kept
    make(".s4.xyz.tmp-" + dead + ".another-node", false);  // another host's: kept
    std::ofstream(s.path("io/.summary.csv.tmp-" + dead + "." + host)) << "rows";  // removed
    const Run resumed = s.batch(
        "--seeds 1-4 --count 60 --arrangement loose-random --out-pattern 'packs/s{seed}.xyz' "
        "--skip-existing "
        "--progress-seconds 0");
    BOOST_REQUIRE(resumed.status == 0);
    BOOST_TEST(
        resumed.err.find("sgmp batch: removed 3 temporaries of killed runs") != std::string::npos,
        resumed.err);
    std::vector<std::string> left;
    for (const auto& entry : fs::recursive_directory_iterator(s.path("io"))) {
        if (entry.path().filename().string().find(".tmp-") != std::string::npos) {
            left.push_back(entry.path().filename().string());
        }
    }
    std::sort(left.begin(), left.end());
    BOOST_TEST(left == (std::vector<std::string>{".s3.xyz.tmp-" + alive + "." + host,
                                                 ".s4.xyz.tmp-" + dead + ".another-node"}));
    for (int seed = 1; seed <= 4; ++seed) {
        BOOST_TEST(fs::exists(s.path("io/packs/s" + std::to_string(seed) + ".xyz")));
    }
}
