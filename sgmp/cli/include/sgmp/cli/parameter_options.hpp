#pragma once
/// @file parameter_options.hpp
/// Command-line options from the rows of a parameter table (sgmp/pack/parameter_table.hpp):
/// `--name` with the row's help, type name (FLOAT, INT, UINT or TEXT) and default, parsed
/// straight into the request by the row. A value the row refuses is kept as
/// "--name VALUE: RULE" and reported once parsing is done (throw_refused), so --help and
/// missing options come first.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "sgmp/cli/run_main.hpp"
#include "sgmp/pack/parameter_table.hpp"

namespace sgmp::cli {

/// The option of one row, bound to `request`; `refused` keeps the first refusal.
template <class Request, class Context>
CLI::Option* add_parameter_option(CLI::App& app, const ParameterRow<Request, Context>& row,
                                  Request& request, std::optional<std::string>& refused) {
    const std::string option = option_name(row.name);
    CLI::Option* added = app.add_option_function<std::string>(
        option,
        [&row, &request, &refused, option](const std::string& text) {
            if (!row.parse(request, text) && !refused) {
                refused = option + " " + (text.empty() ? "\"\"" : text) + ": " + row.rule;
            }
        },
        row.help);
    added->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);  // the last one given counts
    if (row.kind == ValueKind::Number) {
        added->type_name("FLOAT");
    } else if (row.kind == ValueKind::Integer) {
        added->type_name(row.name == "seed" ? "UINT" : "INT");
    }
    if (row.required) {
        added->required();
    } else if (!row.unset_by_default) {
        added->default_str(row.default_text);
    }
    return added;
}

/// Throws UsageError with the first refused value, if any.
inline void throw_refused(const std::optional<std::string>& refused) {
    if (refused) {
        throw UsageError(*refused);
    }
}

}  // namespace sgmp::cli
