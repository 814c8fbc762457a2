#pragma once
/// @file physics_options.hpp
/// The contact physics and settling-rule options shared by `sgmp-reference pour` and
/// `settle` (pour.hpp's PourParams): restitution, rolling friction, Young's modulus,
/// Poisson's ratio, density, gravity, time step, settling threshold and check interval.
#include <CLI/CLI.hpp>

#include "sgmp/reference/pour.hpp"

namespace sgmp::reference {

/// Adds the options into `parameters`, each showing its default in --help.
void add_physics_options(CLI::App& command, PourParams& parameters);

}  // namespace sgmp::reference
