#pragma once
/// @file launcher_options.hpp
/// `--launcher` and `--processors` of `sgmp-reference pour` and `settle` (launcher.hpp).
#include <CLI/CLI.hpp>

#include "sgmp/reference/pour.hpp"

namespace sgmp::reference {

/// Adds --launcher (into request.launcher) and --processors (request.parameters.processors).
void add_launcher_options(CLI::App& command, PourRequest& request);

}  // namespace sgmp::reference
