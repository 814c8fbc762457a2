#pragma once
// `sgmp batch`'s settings as the command line gives them, and the sweep's plan and outputs
// checked before any pack is made (every MPI rank checks the same and stops on the same error).

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sgmp/batch/out_pattern.hpp"
#include "sgmp/batch/parameters.hpp"
#include "sgmp/batch/plan.hpp"
#include "sgmp/batch/run_job.hpp"
#include "sgmp/batch/shard.hpp"
#include "sgmp/batch/summary.hpp"
#include "sgmp/batch/world.hpp"
#include "sgmp/pack/output_lock.hpp"

namespace sgmp::app {

/// Exit status 2: an option value breaks its rule. Status 1: files (existing, unwritable).
struct BadValue {
    std::string message;
};
struct FileProblem {
    std::string message;
};

/// `sgmp batch`'s options as parsed: the grid's values per parameter, the outputs, the run.
struct Settings {
    std::string seeds;
    std::vector<std::vector<std::string>> values =
        std::vector<std::vector<std::string>>(batch::parameters().size());
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
std::string read_text(const std::filesystem::path& path);

/// The summary's columns: the batch's own and sgmp-compare's metric columns (none in a
/// build without the metrics, SGMP_BUILD_REPORT=OFF).
const batch::SummarySchema& schema();

/// The sweep's jobs: --seeds × the grid, with --size-distribution files read (and refused)
/// once. Throws BadValue or FileProblem.
batch::Plan plan_of(const Settings& s);

/// Seconds of packs an earlier summary at the same path records, by pack path.
std::map<std::string, std::string> earlier_seconds(const Settings& s);

/// The packs' file-name pattern; none with --no-packs. Throws BadValue when packs are
/// written but no --out-pattern names them.
std::optional<batch::OutPattern> pattern_of(const Settings& s, const batch::Plan& plan);

/// Rank 0 takes the summary's lock into `lock`: one batch writes a summary at a time, so a
/// second batch naming it is refused now, not left to lose its rows (or the first's) to the
/// last rename. Every rank stops when rank 0 could not take it.
void lock_summary(const Settings& s, const batch::World& world, std::optional<OutputLock>& lock);

/// Throws BadValue when the shard holds more than kMaxJobsPerBatch jobs: each job keeps its
/// summary row (about 0.9 kB, measured at 10⁶ jobs: 884 MB) until the table is written.
void check_job_limit(const batch::Plan& plan, const batch::Shard& shard);

/// The shard's outputs checked before any pack is made: none exists unless --force or
/// --skip-existing says what to do with it, every pack directory can be written, and a
/// resume (rank 0) first removes the temporaries of killed runs. Every rank stops together.
void check_shard_outputs(const Settings& s, const batch::World& world, const batch::Plan& plan,
                         const batch::OutPattern* pattern,
                         const std::vector<std::size_t>& shard_jobs);

}  // namespace sgmp::app
