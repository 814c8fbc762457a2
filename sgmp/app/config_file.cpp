#include "config_file.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <stdexcept>

namespace sgmp::app {

std::vector<std::string> config_arguments(std::istream& in, const std::string& command) {
    std::vector<std::string> injected;
    for (const CLI::ConfigItem& item : CLI::ConfigTOML().from_config(in)) {
        if (item.name == "++" || item.name == "--") {
            continue;  // section markers
        }
        if (!item.parents.empty() && item.parents != std::vector<std::string>{command}) {
            throw std::invalid_argument("key '" + item.fullname() + "' belongs to no option of '" +
                                        command + "'");
        }
        // Pack headers record parameters in snake_case: accept those names too.
        std::string name = item.name;
        std::replace(name.begin(), name.end(), '_', '-');
        const std::string option = "--" + name;
        if (item.inputs.size() == 1 && (item.inputs[0] == "true" || item.inputs[0] == "false")) {
            if (item.inputs[0] == "true") {
                injected.push_back(option);  // a flag
            }
            continue;
        }
        injected.push_back(option);
        injected.insert(injected.end(), item.inputs.begin(), item.inputs.end());
    }
    return injected;
}

}  // namespace sgmp::app
