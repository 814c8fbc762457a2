#pragma once
// `sgmp pack --config FILE`: the file's `key = value` lines (TOML/INI, keys named as the
// long options — `phi-target` or, as pack headers write it, `phi_target` — optionally in
// a [pack] / [arrange] section) become options placed before the command line's own, so
// options typed on the command line win. With `size_distribution` present, a
// `size_modes` key (a blend's header records both) is the distribution's record and is
// left out; sizes typed on the command line in either form replace both keys.

#include <functional>
#include <istream>
#include <string>
#include <vector>

namespace sgmp::app {

/// The command-line arguments a config file stands for. `known("--option")` tells an
/// option of the command; a key whose option `typed` on the command line is left out, so
/// the command line wins for lists too (a grid option's values would otherwise add up).
/// Throws std::invalid_argument (a key in a section other than `command`'s, or a key
/// naming no option) or CLI::ParseError (malformed TOML).
std::vector<std::string> config_arguments(std::istream& in, const std::string& command,
                                          const std::function<bool(const std::string&)>& known,
                                          const std::function<bool(const std::string&)>& typed);

}  // namespace sgmp::app
