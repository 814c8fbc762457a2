#pragma once
/// @file pour_parameter_options.hpp
/// The options of `sgmp-reference pour` and `settle` that set the pour's parameters: one per
/// row of the pour parameter table (sgmp/reference/pour_parameters.hpp), each showing its
/// default in --help and parsed into PourParams by its row.
#include <CLI/CLI.hpp>
#include <optional>
#include <set>
#include <string>

#include "sgmp/reference/pour_params.hpp"

namespace sgmp::reference {

/// Adds the options of the rows named in `names` (every row when empty), in table order;
/// the rows in `required` must be given. A refused value is kept in `refused`
/// (cli::throw_refused reports it).
void add_pour_parameter_options(CLI::App& command, PourParams& parameters,
                                std::optional<std::string>& refused,
                                const std::set<std::string>& names,
                                const std::set<std::string>& required);

}  // namespace sgmp::reference
