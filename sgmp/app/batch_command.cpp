// sgmp batch — many packs in one process.
//   sgmp batch --seeds 1-1000 --count 1000,10000 --arrangement loose-random,small-dense
//              [--relax none,frictionless] [any protocol option, lists allowed]
//              --out-pattern 'packs/{arrangement}/n{count}-s{seed}.xyz.gz' [--no-packs]
//              [--measure [--voronoi]] [--summary summary.csv] [--skip-existing | --force]
//              [--shard I/N] [--threads T] [--progress-seconds S] [--config FILE]
//   sgmp batch --merge shard-1.csv shard-2.csv … --summary summary.csv [--force]
// Under `mpirun -np K` the ranks split the jobs; rank 0 writes the summary.
#include "batch_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "sgmp/batch/executor.hpp"
#include "sgmp/batch/out_pattern.hpp"
#include "sgmp/batch/run_job.hpp"
#include "sgmp/batch/seed_list.hpp"
#include "sgmp/batch/shard.hpp"
#include "sgmp/batch/world.hpp"
#include "sgmp/cli/run_main.hpp"
#include "sgmp/pack/size_modes.hpp"
#if SGMP_WITH_METRICS
#include "sgmp/metrics/parallel.hpp"
#include "sgmp/metrics/summary_columns.hpp"
#endif
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/bounded_file.hpp"
#include "sgmp/pack/cpu_budget.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/output_lock.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/parameter_error.hpp"

namespace sgmp::app {
namespace fs = std::filesystem;
using namespace sgmp::batch;

namespace {

/// Exit status 2: an option value breaks its rule. Status 1: files (existing, unwritable).
struct BadValue {
    std::string message;
};
struct FileProblem {
    std::string message;
};

struct Settings {
    std::string seeds;
    std::vector<std::vector<std::string>> values =
        std::vector<std::vector<std::string>>(parameters().size());
    std::string out_pattern;
    std::string summary = "summary.csv";
    bool no_packs = false;
    bool measure = false;
    bool voronoi = false;
    bool skip_existing = false;
    bool force = false;
    std::string shard;
    unsigned threads = 0;
    double progress_seconds = 5.0;
    std::string config;
    std::vector<std::string> merge;
};

/// A batch summary's text, at most kMaxSummaryBytes (bounded_file.hpp).
std::string read_text(const fs::path& path) {
    try {
        return read_bounded_file(path, kMaxSummaryBytes, "a batch summary");
    } catch (const InputError& e) {
        throw FileProblem{e.what()};
    }
}

/// The summary's columns: the batch's own and sgmp-compare's metric columns (none in a
/// build without the metrics, SGMP_BUILD_REPORT=OFF).
const SummarySchema& schema() {
#if SGMP_WITH_METRICS
    static const SummarySchema schema(metrics::summary_column_names());
#else
    static const SummarySchema schema(std::vector<std::string>{});
#endif
    return schema;
}

/// The measure callback of --measure.
MeasureFields measure_callback(const Settings& s) {
#if SGMP_WITH_METRICS
    // Packs run side by side; each measurement is serial (one thread).
    return [voronoi = s.voronoi](const Pack& pack) {
        return metrics::summary_fields(pack, voronoi, 1);
    };
#else
    (void)s;
    throw BadValue{"--measure: this sgmp was built without the metrics (SGMP_BUILD_REPORT=OFF)"};
#endif
}

void write_summary(const Settings& s, const std::string& text) {
    write_file_atomically(s.summary, s.force || s.skip_existing,
                          [&](std::ostream& out) { out << text; });
}

int run_merge(const Settings& s) {
    try {
        check_writable(s.summary, s.force);
    } catch (const std::runtime_error& e) {
        throw FileProblem{std::string("--summary ") + e.what()};
    }
    std::vector<SummaryTable> tables;
    for (const std::string& path : s.merge) {
        tables.push_back(cli::while_doing("reading the summary " + path,
                                          [&] { return schema().parse(read_text(path), path); }));
    }
    const std::string text = schema().merge(tables);
    write_file_atomically(s.summary, s.force, [&](std::ostream& out) { out << text; });
    std::size_t rows = 0;
    for (const auto& t : tables) {
        rows += t.rows.size();
    }
    std::printf("sgmp: merged %zu summaries, %zu rows -> %s\n", tables.size(), rows,
                s.summary.c_str());
    return 0;
}

/// The text of every --size-distribution value that names a file (not a lognormal: spec).
DistributionFiles read_distribution_files(const Settings& s) {
    DistributionFiles files;
    for (const std::string& value : s.values[parameter_index("size_distribution")]) {
        if (value.empty() || sgmp::is_lognormal(value)) {
            continue;
        }
        if (!fs::is_regular_file(value)) {
            throw BadValue{"--size-distribution " + value +
                           ": must name a readable file or be lognormal:MEDIAN:SIGMA[...]"};
        }
        std::string text;
        try {
            text = read_bounded_file(value, kMaxSmallFileBytes, "a size distribution file");
        } catch (const InputError& e) {  // a file that cannot be read: exit 1
            throw FileProblem{std::string("--size-distribution ") + e.what()};
        }
        try {
            (void)sgmp::parse_size_distribution_csv(text, value);  // refused here, once
        } catch (const InputError& e) {
            throw BadValue{std::string("--size-distribution ") + e.what()};
        }
        files.emplace(value, std::move(text));
    }
    return files;
}

Plan plan_of(const Settings& s) {
    Grid grid;
    grid.values = s.values;
    grid.seeds = parse_seed_list(s.seeds);
    grid.distribution_files = read_distribution_files(s);
    return make_plan(grid);
}

/// Seconds of packs an earlier summary at the same path records, by pack path.
std::map<std::string, std::string> earlier_seconds(const Settings& s) {
    std::map<std::string, std::string> seconds;
    if (!s.skip_existing || !fs::exists(s.summary)) {
        return seconds;
    }
    const auto header = schema().header();
    const auto column = [&](const char* name) {
        return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) -
                                        header.begin());
    };
    try {
        for (const auto& row : schema().parse(read_text(s.summary), s.summary).rows) {
            if (!row.fields[column("path")].empty()) {
                seconds[row.fields[column("path")]] = row.fields[column("seconds")];
            }
        }
    } catch (const InputError&) {
        seconds.clear();  // an unreadable earlier summary only costs the timings
    }
    return seconds;
}

/// The first job output that exists although neither --force nor --skip-existing is given.
std::string first_existing(const Settings& s, const Plan& plan, const OutPattern* pattern,
                           const std::vector<std::size_t>& jobs) {
    if (s.force || s.skip_existing) {
        return {};
    }
    if (fs::exists(s.summary)) {
        return s.summary;
    }
    for (std::size_t i = 0; pattern != nullptr && i < jobs.size(); ++i) {
        const std::string name = pattern->expand(plan, jobs[i]);
        if (fs::exists(name)) {
            return name;
        }
    }
    return {};
}

/// Throws FileProblem when a pack's directory cannot be made or written (checked once per
/// directory, before any pack is made; nothing is created here).
void check_pack_directories(const Plan& plan, const OutPattern& pattern,
                            const std::vector<std::size_t>& jobs) {
    std::set<fs::path> seen;
    for (const std::size_t job : jobs) {
        const fs::path name = pattern.expand(plan, job);
        fs::path dir = name.parent_path().empty() ? fs::path(".") : name.parent_path();
        if (!seen.insert(dir).second) {
            continue;
        }
        while (!fs::exists(dir) && dir.has_parent_path() && dir != dir.parent_path()) {
            dir = dir.parent_path();  // the nearest existing ancestor is where it is created
        }
        if (fs::exists(dir) && (!fs::is_directory(dir) || ::access(dir.c_str(), W_OK) != 0)) {
            throw FileProblem{
                name.string() + ": cannot be written (" + dir.string() +
                (fs::is_directory(dir) ? " is not writable)" : " is not a directory)")};
        }
    }
}

/// A resume's clean-up: the temporaries that killed writers on this host left beside the
/// summary and in the packs' directories (each directory once).
void remove_stale_temporaries_of(const Settings& s, const Plan& plan, const OutPattern* pattern,
                                 const std::vector<std::size_t>& jobs) {
    const auto directory_of = [](const fs::path& file) {
        return file.parent_path().empty() ? fs::path(".") : file.parent_path();
    };
    std::set<fs::path> directories{directory_of(s.summary)};
    for (std::size_t i = 0; pattern != nullptr && i < jobs.size(); ++i) {
        directories.insert(directory_of(pattern->expand(plan, jobs[i])));
    }
    std::size_t removed = 0;
    for (const fs::path& directory : directories) {
        removed += remove_stale_temporaries(directory);
    }
    if (removed > 0) {
        std::fprintf(stderr, "sgmp batch: removed %zu temporaries of killed runs\n", removed);
    }
}

class ProgressLine {
  public:
    ProgressLine(std::size_t total, const World& world) : total_(total), world_(world) {}
    void operator()(std::size_t done, double seconds) const {
        const double rate = seconds > 0.0 ? static_cast<double>(done) / seconds : 0.0;
        // No time left is guessed before the first pack is done.
        char left[32] = "time left unknown yet";
        if (rate > 0.0) {
            std::snprintf(left, sizeof left, "%.0f s left",
                          static_cast<double>(total_ - done) / rate);
        }
        std::fprintf(
            stderr, "sgmp batch: %zu / %zu packs%s (%.1f%%), %.1f packs/s, %s\n", done, total_,
            world_.size() > 1 ? " on rank 0" : "",
            total_ == 0 ? 100.0 : 100.0 * static_cast<double>(done) / static_cast<double>(total_),
            rate, left);
        std::fflush(stderr);
    }

  private:
    std::size_t total_;
    const World& world_;
};

int run_sweep(const Settings& s, const World& world) {
    const Plan plan = plan_of(s);
    std::optional<OutPattern> pattern;
    if (!s.no_packs) {
        if (s.out_pattern.empty()) {
            throw BadValue{"--out-pattern: needed to name the packs (or pass --no-packs)"};
        }
        pattern.emplace(s.out_pattern, plan);
    }
    const Shard shard = s.shard.empty() ? Shard{} : parse_shard(s.shard);
    if (s.force && s.skip_existing) {
        throw BadValue{"--force and --skip-existing: choose one (remake or keep existing packs)"};
    }
    // Every rank checks the same things and so stops on the same error.
    try {
        check_writable(s.summary, true);  // its directory; an existing summary comes next
    } catch (const std::runtime_error& e) {
        throw FileProblem{std::string("--summary ") + e.what()};
    }
    // One batch writes a summary at a time: a second batch naming it is refused now, not
    // left to lose its rows (or the first's) to the last rename. Only rank 0 writes it.
    std::optional<OutputLock> summary_lock;
    std::string lock_problem;
    if (world.rank() == 0) {
        try {
            summary_lock.emplace(s.summary);
        } catch (const std::runtime_error& e) {
            lock_problem = std::string("--summary ") + e.what() +
                           "; give each batch its own --summary and join them with --merge";
        }
    }
    if (!world.all(lock_problem.empty())) {
        if (world.rank() == 0) {
            std::cerr << "sgmp: " << printable(lock_problem) << "\n";
        }
        world.abort(1);
    }
    // Each job keeps its summary row (about 0.9 kB, measured at 10⁶ jobs: 884 MB) until the
    // table is written, so one batch runs at most kMaxJobsPerBatch of them.
    const std::uint64_t total = plan.job_count();
    const std::uint64_t in_shard =
        total >= shard.index ? (total - shard.index) / shard.count + 1 : 0;
    if (in_shard > kMaxJobsPerBatch) {
        const std::uint64_t shards = (total + kMaxJobsPerBatch - 1) / kMaxJobsPerBatch;
        throw BadValue{"the grid holds " + std::to_string(total) + " jobs (" +
                       std::to_string(in_shard) + " in this shard); one batch runs at most " +
                       std::to_string(kMaxJobsPerBatch) + ": split it with --shard I/" +
                       std::to_string(shards) + " or more shards"};
    }
    const std::vector<std::size_t> shard_jobs = assigned_jobs(plan.job_count(), shard);
    if (const std::string existing =
            first_existing(s, plan, pattern ? &*pattern : nullptr, shard_jobs);
        !existing.empty()) {
        throw FileProblem{existing +
                          ": exists; pass --skip-existing to keep what is there or --force to "
                          "remake it"};
    }
    if (pattern) {
        check_pack_directories(plan, *pattern, shard_jobs);
    }
    if (s.skip_existing && world.rank() == 0) {
        remove_stale_temporaries_of(s, plan, pattern ? &*pattern : nullptr, shard_jobs);
    }
    if (!world.all(true)) {
        world.abort(1);
    }
    const std::vector<std::size_t> jobs =
        assigned_jobs(plan.job_count(), shard, world.rank(), world.size());
    const unsigned threads = s.threads > 0 ? s.threads : usable_threads();
    const auto seconds = earlier_seconds(s);
    JobOptions options;
    if (s.measure) {
        options.measure = measure_callback(s);
    }
    std::atomic<std::size_t> reused{0};
    const auto work = [&](std::size_t position) {
        const std::size_t job = jobs[position];
        const std::string path = pattern ? pattern->expand(plan, job) : std::string();
        if (s.skip_existing && !path.empty() && fs::exists(path)) {
            SummaryRow row = reused_row(plan, job, read_pack_file(path), options, path);
            if (const auto found = seconds.find(path);
                found != seconds.end() && !found->second.empty()) {
                row.seconds = std::stod(found->second);
            }
            ++reused;
            return schema().line(row);
        }
        const JobResult result = run_job(plan, job, options, path);
        if (!path.empty()) {
            try {
                write_pack_file(path, result.pack, s.force);
            } catch (const FileExists&) {
                if (!s.skip_existing) {
                    throw;
                }
                // Another batch made this pack meanwhile: it is kept, as if it had been
                // there at the start.
                ++reused;
                return schema().line(reused_row(plan, job, read_pack_file(path), options, path));
            }
        }
        return schema().line(result.row);
    };
    const auto start = std::chrono::steady_clock::now();
    const ProgressLine progress(jobs.size(), world);
    std::vector<std::string> lines;
    try {
        lines = run_jobs(jobs.size(), threads, work, world.rank() == 0 ? s.progress_seconds : 0.0,
                         progress);
    } catch (const std::exception& e) {
        std::cerr << "sgmp: " << printable(e.what()) << "\n";
        world.abort(1);
    }
    std::string mine;
    for (const std::string& line : lines) {
        mine += line;
    }
    const std::vector<std::string> texts = world.gather(mine);
    const std::vector<std::string> reused_by_rank = world.gather(std::to_string(reused.load()));
    if (world.rank() != 0) {
        return 0;
    }
    std::size_t reused_in_all = 0;
    for (const std::string& count : reused_by_rank) {
        reused_in_all += std::stoul(count);
    }
    std::vector<SummaryTable> tables;
    for (std::size_t r = 0; r < texts.size(); ++r) {
        tables.push_back(schema().parse(schema().text({texts[r]}), "rank " + std::to_string(r)));
    }
    write_summary(s, schema().merge(tables));
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "sgmp: batch of %zu packs (%zu reused) on %zu rank(s) x %u thread(s), %.3f s, "
        "%.1f packs/s on rank 0 -> %s\n",
        plan.job_count() / shard.count, reused_in_all, world.size(), threads, elapsed,
        elapsed > 0.0 ? static_cast<double>(jobs.size()) / elapsed : 0.0, s.summary.c_str());
    return 0;
}

void add_grid_options(CLI::App& batch, Settings& s) {
    for (std::size_t i = 0; i < parameters().size(); ++i) {
        const Parameter& p = parameters()[i];
        std::string option = p.name;
        std::replace(option.begin(), option.end(), '_', '-');
        auto* added = batch.add_option(
            "--" + option, s.values[i],
            p.list_valued ? "values of --" + option + " (repeat the option for several)"
                          : "values of --" + option + " (comma-separated or repeated)" +
                                (p.default_value.empty() ? "" : "; default " + p.default_value));
        added->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
        if (!p.list_valued) {
            added->delimiter(',');
        }
    }
}

}  // namespace

struct BatchCommand::State {
    CLI::App* command = nullptr;
    Settings settings;
};

BatchCommand::BatchCommand(CLI::App& app) : state_(std::make_unique<State>()) {
    Settings& s = state_->settings;
    CLI::App* b = app.add_subcommand(
        "batch", "make many packs in one process: seed lists x a parameter grid, one summary.csv");
    state_->command = b;
    b->add_option("--seeds", s.seeds, "seeds: S, ranges A-B, comma-separated (1-100000, 1,5,9-12)");
    add_grid_options(*b, s);
    b->add_option("--out-pattern", s.out_pattern,
                  "pack file names: {seed}, {job} and {PARAMETER} placeholders, e.g. "
                  "'packs/{arrangement}/n{count}-s{seed}.xyz.gz'");
    b->add_option("--summary", s.summary, "the sweep's table (default summary.csv)");
    b->add_flag("--no-packs", s.no_packs, "write no pack files, only the summary");
    b->add_flag("--measure", s.measure,
                "measure every pack in process (phi, Z at every tolerance, overlaps, split ratio)");
    b->add_flag("--voronoi", s.voronoi, "with --measure: the Voronoi mean local phi too (slower)");
    b->add_flag("--skip-existing", s.skip_existing,
                "keep packs that exist (an interrupted batch resumes; they are read back for "
                "their rows)");
    b->add_flag("--force", s.force, "remake packs and the summary that exist");
    b->add_option("--shard", s.shard, "I/N: make only jobs j with j mod N = I - 1 (1 <= I <= N)");
    b->add_option("--threads", s.threads,
                  "packs made side by side (default: the CPUs the process may use)")
        ->check(CLI::Range(0u, 256u));
    b->add_option("--progress-seconds", s.progress_seconds,
                  "a progress line on stderr this often (default 5; 0: none)")
        ->check(CLI::Range(0.0, 86400.0));
    b->add_option("--config", s.config,
                  "read options from a TOML/INI file of 'option = value' lines (lists as "
                  "count = [1000, 10000]); the command line wins");
    b->add_option("--merge", s.merge, "merge these shard summaries into --summary, in job order")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

BatchCommand::~BatchCommand() = default;

bool BatchCommand::parsed() const {
    return state_->command->parsed();
}

int BatchCommand::run() {
    const Settings& s = state_->settings;
    try {
        if (!s.merge.empty()) {
            return run_merge(s);
        }
        if (s.seeds.empty()) {
            throw BadValue{"--seeds: needed, e.g. --seeds 1-1000"};
        }
        const World world;
        return run_sweep(s, world);
    } catch (const BadValue& e) {
        std::cerr << "sgmp: " << printable(e.message) << "\n";
        return 2;
    } catch (const ParameterError& e) {  // named as headers do; said as the option is typed
        std::cerr << "sgmp: " << printable(cli::usage_message(e)) << "\n";
        return 2;
    } catch (const std::invalid_argument& e) {
        std::cerr << "sgmp: " << printable(e.what()) << "\n";
        return 2;
    } catch (const FileProblem& e) {
        std::cerr << "sgmp: " << printable(excerpt(e.message, cli::kMaxMessageBytes)) << "\n";
        return 1;
    } catch (const std::bad_alloc&) {
        std::cerr << "sgmp: " << cli::out_of_memory_message("sgmp batch") << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "sgmp: " << printable(excerpt(cli::failure_message(e), cli::kMaxMessageBytes))
                  << "\n";
        return 1;
    }
}

}  // namespace sgmp::app
