// sgmp batch — many packs in one process.
//   sgmp batch --seeds 1-1000 --count 1000,10000 --arrangement loose-random,small-dense
//              [--relax none,frictionless] [any protocol option, lists allowed]
//              --out-pattern 'packs/{arrangement}/n{count}-s{seed}.xyz.gz' [--no-packs]
//              [--measure [--voronoi]] [--summary summary.csv] [--skip-existing | --force]
//              [--shard I/N] [--threads T] [--progress-seconds S] [--config FILE]
//   sgmp batch --merge shard-1.csv shard-2.csv … --summary summary.csv [--force]
// Under `mpirun -np K` the ranks split the jobs; rank 0 writes the summary.
#include "batch_command.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "batch_plan.hpp"
#include "sgmp/batch/executor.hpp"
#include "sgmp/batch/out_pattern.hpp"
#include "sgmp/batch/run_job.hpp"
#include "sgmp/batch/shard.hpp"
#include "sgmp/batch/world.hpp"
#include "sgmp/cli/run_main.hpp"
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

/// One job of a sweep as its summary line: the pack made (and written, when packs are), or
/// with --skip-existing read back from the file that is there. Counts reused packs.
class SweepJob {
  public:
    SweepJob(const Settings& s, const Plan& plan, const OutPattern* pattern,
             const JobOptions& options)
        : s_(s), plan_(plan), pattern_(pattern), options_(options), seconds_(earlier_seconds(s)) {}

    /// The summary line of job `job` of the plan.
    std::string operator()(std::size_t job) {
        const std::string path = pattern_ != nullptr ? pattern_->expand(plan_, job) : std::string();
        if (s_.skip_existing && !path.empty() && fs::exists(path)) {
            SummaryRow row = reused_row(plan_, job, read_pack_file(path), options_, path);
            if (const auto found = seconds_.find(path);
                found != seconds_.end() && !found->second.empty()) {
                row.seconds = std::stod(found->second);
            }
            ++reused_;
            return schema().line(row);
        }
        const JobResult result = run_job(plan_, job, options_, path);
        if (!path.empty()) {
            try {
                write_pack_file(path, result.pack, s_.force);
            } catch (const FileExists&) {
                if (!s_.skip_existing) {
                    throw;
                }
                // Another batch made this pack meanwhile: it is kept, as if it had been
                // there at the start.
                ++reused_;
                return schema().line(reused_row(plan_, job, read_pack_file(path), options_, path));
            }
        }
        return schema().line(result.row);
    }

    /// Packs read back instead of made so far.
    std::size_t reused() const { return reused_.load(); }

  private:
    const Settings& s_;
    const Plan& plan_;
    const OutPattern* pattern_;
    const JobOptions& options_;
    std::map<std::string, std::string> seconds_;  // of an earlier summary, by pack path
    std::atomic<std::size_t> reused_{0};
};

/// What this rank's part of a sweep gave: its summary lines and its count of reused packs.
struct RankResult {
    std::string lines;
    std::size_t reused = 0;
};

/// Gathers every rank's lines on rank 0, which writes the summary and prints the closing
/// line; the other ranks return at once.
void write_sweep_summary(const Settings& s, const World& world, const Plan& plan,
                         const Shard& shard, const RankResult& mine, std::size_t rank_jobs,
                         unsigned threads, std::chrono::steady_clock::time_point start) {
    const std::vector<std::string> texts = world.gather(mine.lines);
    const std::vector<std::string> reused_by_rank = world.gather(std::to_string(mine.reused));
    if (world.rank() != 0) {
        return;
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
        elapsed > 0.0 ? static_cast<double>(rank_jobs) / elapsed : 0.0, s.summary.c_str());
}

/// A sweep: its options and outputs checked on every rank (so all stop on the same error),
/// this rank's jobs run on its threads, and the summary written by rank 0.
int run_sweep(const Settings& s, const World& world) {
    const Plan plan = plan_of(s);
    const std::optional<OutPattern> pattern = pattern_of(s, plan);
    const OutPattern* pattern_ptr = pattern ? &*pattern : nullptr;
    const Shard shard = s.shard.empty() ? Shard{} : parse_shard(s.shard);
    if (s.force && s.skip_existing) {
        throw BadValue{"--force and --skip-existing: choose one (remake or keep existing packs)"};
    }
    try {
        check_writable(s.summary, true);  // its directory; an existing summary comes next
    } catch (const std::runtime_error& e) {
        throw FileProblem{std::string("--summary ") + e.what()};
    }
    std::optional<OutputLock> summary_lock;
    lock_summary(s, world, summary_lock);
    check_job_limit(plan, shard);
    check_shard_outputs(s, world, plan, pattern_ptr, assigned_jobs(plan.job_count(), shard));
    const std::vector<std::size_t> jobs =
        assigned_jobs(plan.job_count(), shard, world.rank(), world.size());
    const unsigned threads = s.threads > 0 ? s.threads : usable_threads();
    JobOptions options;
    if (s.measure) {
        options.measure = measure_callback(s);
    }
    SweepJob sweep_job(s, plan, pattern_ptr, options);
    const auto work = [&](std::size_t position) { return sweep_job(jobs[position]); };
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
    RankResult mine;
    for (const std::string& line : lines) {
        mine.lines += line;
    }
    mine.reused = sweep_job.reused();
    write_sweep_summary(s, world, plan, shard, mine, jobs.size(), threads, start);
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
