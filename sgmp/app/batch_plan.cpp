// `sgmp batch`'s plan (seeds × grid, size-distribution files read once) and the checks of
// its outputs before any pack is made: existing files, writable directories, the summary's
// lock, the jobs a batch may hold, the temporaries of killed runs.
#include "batch_plan.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <set>

#include "sgmp/batch/seed_list.hpp"
#include "sgmp/pack/size_modes.hpp"
#if SGMP_WITH_METRICS
#include "sgmp/metrics/summary_columns.hpp"
#endif
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/bounded_file.hpp"
#include "sgmp/pack/input_error.hpp"

namespace sgmp::app {
namespace fs = std::filesystem;
using namespace sgmp::batch;

namespace {

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

}  // namespace

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

/// The sweep's jobs: --seeds × the grid, with --size-distribution files read (and refused)
/// once.
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

/// The packs' file-name pattern; none with --no-packs. Throws BadValue when packs are
/// written but no --out-pattern names them.
std::optional<OutPattern> pattern_of(const Settings& s, const Plan& plan) {
    std::optional<OutPattern> pattern;
    if (!s.no_packs) {
        if (s.out_pattern.empty()) {
            throw BadValue{"--out-pattern: needed to name the packs (or pass --no-packs)"};
        }
        pattern.emplace(s.out_pattern, plan);
    }
    return pattern;
}

/// Rank 0 takes the summary's lock into `lock`: one batch writes a summary at a time, so a
/// second batch naming it is refused now, not left to lose its rows (or the first's) to the
/// last rename. Every rank stops when rank 0 could not take it.
void lock_summary(const Settings& s, const World& world, std::optional<OutputLock>& lock) {
    std::string lock_problem;
    if (world.rank() == 0) {
        try {
            lock.emplace(s.summary);
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
}

/// Throws BadValue when the shard holds more than kMaxJobsPerBatch jobs: each job keeps its
/// summary row (about 0.9 kB, measured at 10⁶ jobs: 884 MB) until the table is written.
void check_job_limit(const Plan& plan, const Shard& shard) {
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
}

/// The shard's outputs checked before any pack is made: none exists unless --force or
/// --skip-existing says what to do with it, every pack directory can be written, and a
/// resume (rank 0) first removes the temporaries of killed runs. Every rank stops together.
void check_shard_outputs(const Settings& s, const World& world, const Plan& plan,
                         const OutPattern* pattern, const std::vector<std::size_t>& shard_jobs) {
    if (const std::string existing = first_existing(s, plan, pattern, shard_jobs);
        !existing.empty()) {
        throw FileProblem{existing +
                          ": exists; pass --skip-existing to keep what is there or --force to "
                          "remake it"};
    }
    if (pattern != nullptr) {
        check_pack_directories(plan, *pattern, shard_jobs);
    }
    if (s.skip_existing && world.rank() == 0) {
        remove_stale_temporaries_of(s, plan, pattern, shard_jobs);
    }
    if (!world.all(true)) {
        world.abort(1);
    }
}

}  // namespace sgmp::app
