#pragma once
/// @file input_script.hpp
/// The LIGGGHTS input script of a pour, filled in from the templates of
/// reference/templates/ (compiled into the library).

#include <map>
#include <string>

#include "sgmp/reference/pour_params.hpp"

namespace sgmp::reference {

/// The text of an embedded template ("pour.in", "start-cloud.in", "start-arrangement.in").
const std::string& embedded_template(const std::string& name);

/// Replaces every `{{key}}` in `text` by `values.at(key)`; `{{key:W}}` pads the value with
/// spaces to W characters (aligned comments). Throws std::invalid_argument
/// for a placeholder without a value or an unterminated `{{`.
std::string fill_template(const std::string& text,
                          const std::map<std::string, std::string>& values);

/// Top of the simulation box: room above the start for spheres thrown upwards,
/// start_top + f·(start_top − floor) + 4·d with f = ¼ for equal spheres and f = 1 for a
/// blend, whose fines can be squeezed out between converging coarse spheres faster than
/// they fell (a trimodal pour of 15000 shot a fine sphere up to 1.35 drop heights above
/// the floor, reference/docs/pour-physics.md).
double domain_top(double start_top, double diameter, bool blend);

/// The complete input script. `start_top` is the top of the starting positions (the cloud
/// top, or the highest sphere of an arrangement), which sets the box and the fall phase.
std::string pour_script(const PourParams& parameters, double start_top);

/// The "processors" grid "PX PY PZ" of a pour: its `processors` when given, else chosen
/// from the container's shape for its ranks (launcher.hpp).
std::string processor_grid(const PourParams& parameters);

}  // namespace sgmp::reference
