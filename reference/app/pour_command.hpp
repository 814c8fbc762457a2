#pragma once
/// @file pour_command.hpp
/// `sgmp-reference pour --count N --friction MU --seed S --out OUT`: N equal spheres
/// poured into the container with LIGGGHTS (pour.hpp) from a loose random cloud or from
/// an SGMP starting arrangement, written as a pack file.
#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>

#include "sgmp/reference/pour.hpp"

namespace sgmp::reference {

struct PourOptions {
    PourRequest request;
    std::string out;
    std::string keep_work;
    std::string arrangement;
    std::string size_distribution;  ///< a CSV file or lognormal:…, read by run_pour
    CLI::Option* size_modes_option = nullptr;
    double timeout = 0.0;
    bool force = false;
    bool quiet = false;
    /// The first parameter value refused while parsing (cli::throw_refused).
    std::optional<std::string> refused;
};

/// Adds the `pour` subcommand with its options to `app`.
CLI::App* add_pour_command(CLI::App& app, PourOptions& options);

/// Runs it: 0 when the pack is written. Bad parameters throw ParameterError and a bad
/// output path cli::UsageError (exit 2 through run_main); a failed pour prints its message
/// and the tail of the LIGGGHTS log and returns 1 (130 when `interrupted`).
int run_pour(PourOptions& options, const PourObserver& observer,
             const std::function<bool()>& interrupted, const std::function<void()>& finish);

/// The one-line summary of a finished run on stderr: "VERB N spheres in … s, … steps;
/// settling measure …; max overlap … d; phi(control volume) …; wrote OUT".
void print_run_summary(const char* verb, const PourResult& result, std::size_t count,
                       const std::string& out);

/// Reports a failed pour or settle on stderr — its one-line message, then the tail of the
/// LIGGGHTS log when there is one — and returns the exit status (130 when interrupted).
int report_run_failure(const std::exception& error, bool interrupted);

}  // namespace sgmp::reference
