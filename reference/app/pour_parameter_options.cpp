#include "pour_parameter_options.hpp"

#include "sgmp/cli/parameter_options.hpp"
#include "sgmp/reference/pour_parameters.hpp"

namespace sgmp::reference {

void add_pour_parameter_options(CLI::App& command, PourParams& parameters,
                                std::optional<std::string>& refused,
                                const std::set<std::string>& names,
                                const std::set<std::string>& required) {
    for (const PourParameter& row : pour_parameters()) {
        if (!names.empty() && names.count(row.name) == 0) {
            continue;
        }
        CLI::Option* option = cli::add_parameter_option(command, row, parameters, refused);
        if (required.count(row.name) != 0) {
            option->required();
        }
    }
}

}  // namespace sgmp::reference
