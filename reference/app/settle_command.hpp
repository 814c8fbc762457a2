#pragma once
/// @file settle_command.hpp
/// `sgmp-reference settle PACK --friction MU --out OUT`: LIGGGHTS started from the spheres of
/// any pack file (an SGMP pack or another pour; equal spheres), at rest, and run until
/// settled by the rule and with the fault handling of `pour` (pour.hpp: the same input
/// script, fall phase of √(2h/g) included, the same settling check and step cap). The
/// written pack records the steps and wall seconds like a pour's, and where it started:
/// `start=pack`, `start_pack` (the file name) and `start_generator`.
#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>

#include "sgmp/reference/pour.hpp"

namespace sgmp::reference {

struct SettleOptions {
    std::string input;
    std::string out;
    std::string keep_work;
    double timeout = 0.0;
    bool force = false;
    bool quiet = false;
    PourRequest request;
    /// The first parameter value refused while parsing (cli::throw_refused).
    std::optional<std::string> refused;
};

/// Adds the `settle` subcommand with its options to `app`.
CLI::App* add_settle_command(CLI::App& app, SettleOptions& options);

/// Runs it: returns the exit status (0; 2 for bad input; 1 for a failed pour; 130 when
/// stopped). Errors go to stderr as one line prefixed with the program's name.
int run_settle(SettleOptions& options, const PourObserver& observer,
               const std::function<bool()>& should_stop, const std::function<void()>& finish);

}  // namespace sgmp::reference
