#pragma once
// Shared pieces of the sgmp-compare commands: options common to every command that
// measures packs, usage errors, and reading and measuring packs with errors that name
// the file.

#include <CLI/CLI.hpp>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sgmp/cli/run_main.hpp"
#include "sgmp/metrics/measure.hpp"
#include "sgmp/pack/pack.hpp"
#include "sgmp/pack/stated_container.hpp"
#include "sgmp/report/agreement.hpp"

namespace sgmp::compare::cli {

// The front end puts the two libraries together: their names are used unqualified here.
using namespace ::sgmp::metrics;
using namespace ::sgmp::report;

/// A usage error: exit status 2 (sgmp/cli/run_main.hpp).
using UsageError = ::sgmp::cli::UsageError;

struct CommonOptions {
    std::vector<double> region;
    MeasureOptions measure;
    std::string gr_density = "neighbours";
    unsigned threads = 0;
    bool timings = false;
    bool force = false;
    std::string out;
    std::vector<std::string> metrics;  // --metrics: batch summaries holding precomputed rows
    std::map<std::string, PackSummary> precomputed;  // their rows by pack path (apply)
    std::string container;                           // --container "x_min x_max z_min z_max floor"
    CLI::Option* container_option = nullptr;         // whether --container was given
    std::optional<StatedContainer> stated;           // --container parsed (apply)
    std::map<std::string, StatedContainer> stated_per_pack;  // a manifest's column, by path
};

/// --out, --force and the measurement options.
/// Two entries of a list of pack files that are one pack, and how: `same_file` (one file
/// by two spellings, a symbolic link: the same canonical path) or byte-identical copies.
struct SamePack {
    std::size_t first = 0;
    std::size_t second = 0;
    bool same_file = false;
};
/// The first pair of `paths` that is one pack (reliability finding 8: `p1.xyz` and
/// `./p1.xyz`, or a copy, counted as two seeds with no spread between them), or nullopt.
/// Files are compared by canonical path, then by their bytes (hashed when two have the same
/// size, then compared); a file that cannot be opened is left to its reader.
std::optional<SamePack> find_same_pack(const std::vector<std::string>& paths);

void add_common(CLI::App* command, CommonOptions& o);
/// --metrics (crossval, report): packs whose metrics are precomputed in batch summaries.
void add_precomputed(CLI::App* command, CommonOptions& o);
/// Validates the options (ParameterError), checks that --out can be written (UsageError)
/// and reads the --metrics summaries.
void apply(CommonOptions& o);
/// "sgmp-compare <arguments>", recorded in outputs.
std::string command_line(int argc, char** argv);
/// The walls stated for the pack at `path`: its manifest row's, else --container's.
std::optional<StatedContainer> stated_for(const std::string& path, const CommonOptions& o);
/// Reads a pack with its container settled (sgmp/pack/stated_container.hpp); InputError for
/// unreadable, empty or malformed files and for a container refused.
Pack read_pack(const std::string& path, const std::optional<StatedContainer>& stated,
               unsigned threads);
Measurement measure_pack(const std::string& path, const Pack& pack, const CommonOptions& o);
/// The measurement parameters as recorded in outputs.
nlohmann::ordered_json measure_parameters(const CommonOptions& o);
/// File name without .gz and the format extension.
std::string stem_of(const std::string& path);
/// Reads and measures `packs` as one labelled group. A path ending in `.metrics.json`
/// (a `measure` output) and a pack found in the --metrics summaries are not measured
/// again: their precomputed metrics are used (sgmp/report/precomputed.hpp).
Group measure_group(const std::string& label, const std::vector<std::string>& packs,
                    const CommonOptions& o);

/// Every subcommand is registered the same way: `register_*` adds it with its options to
/// the app and returns a runner, called with the command line; it returns the exit status
/// when its subcommand was chosen and −1 otherwise.
using CommandRunner = std::function<int(const std::string& command)>;
CommandRunner register_measure(CLI::App& app);   // measure_command.cpp
CommandRunner register_report(CLI::App& app);    // measure_command.cpp
CommandRunner register_header(CLI::App& app);    // measure_command.cpp
CommandRunner register_crossval(CLI::App& app);  // crossval_command.cpp
CommandRunner register_regress(CLI::App& app);   // crossval_command.cpp

}  // namespace sgmp::compare::cli
