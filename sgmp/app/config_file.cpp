#include "config_file.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <stdexcept>

namespace sgmp::app {

namespace {

/// The key with every '_' as '-': headers write snake_case, options kebab-case.
std::string kebab(std::string name) {
    std::replace(name.begin(), name.end(), '_', '-');
    return name;
}

}  // namespace

std::vector<std::string> config_arguments(std::istream& in, const std::string& command,
                                          const std::function<bool(const std::string&)>& known,
                                          const std::function<bool(const std::string&)>& typed) {
    const std::vector<CLI::ConfigItem> items = CLI::ConfigTOML().from_config(in);
    // A blend's header records its distribution and the modes read from it: the
    // distribution is the request, the modes its record. Sizes typed on the command line,
    // in either form, replace both.
    const bool has_distribution = std::any_of(items.begin(), items.end(), [](const auto& item) {
        return kebab(item.name) == "size-distribution";
    });
    const bool sizes_typed = typed("--size-modes") || typed("--size-distribution");
    std::vector<std::string> injected;
    for (const CLI::ConfigItem& item : items) {
        if (item.name == "++" || item.name == "--") {
            continue;  // section markers
        }
        const std::string key = kebab(item.name);
        if (key == "force" || key == "config") {
            // Replacing files is the typist's decision; a file (perhaps someone else's)
            // may not grant it, nor pull in further files.
            throw std::invalid_argument("key '" + item.name +
                                        "' is taken only from the command line (--" + key + ")");
        }
        if ((has_distribution && key == "size-modes") ||
            (sizes_typed && (key == "size-modes" || key == "size-distribution"))) {
            continue;
        }
        if (!item.parents.empty() && item.parents != std::vector<std::string>{command}) {
            throw std::invalid_argument("key '" + item.fullname() + "' belongs to no option of '" +
                                        command + "'");
        }
        // Pack headers record parameters in snake_case: accept those names too.
        const std::string option = "--" + kebab(item.name);
        if (!known(option)) {
            throw std::invalid_argument("key '" + item.name + "' names no option of '" + command +
                                        "' (" + option + ")");
        }
        if (typed(option)) {
            continue;  // the command line's value wins
        }
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
