#pragma once
// `sgmp convert IN OUT [--to FORMAT] [--frame N] [--radius R] [--force]`: a pack file into
// another format (sgmp/pack/pack_format.hpp), with the input's provenance and the
// conversion's own.

#include <CLI/CLI.hpp>

namespace sgmp::app {

/// Adds the `convert` subcommand to `app` and returns it.
CLI::App* register_convert(CLI::App& app);

/// Runs the conversion parsed into the subcommand; returns the exit code (0; 1 bad input
/// or a failed write; 2 a usage error) after printing any error as one line.
int run_convert();

}  // namespace sgmp::app
