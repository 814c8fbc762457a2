#pragma once
/// @file sides.hpp
/// The container's lateral sides (`--sides`): the thesis' walls at x = x_min, x_max and
/// z = z_min, z_max, or periodic x and z (Container::periodic), the floor kept either way.
/// Periodic sides pack bulk material without wall layers (Rocpack-style propellant cells):
/// a sphere near one face meets the images of the spheres near the opposite face, shifted
/// by one period, and every centre is wrapped into the cell when it settles.
#include <optional>
#include <string>
#include <string_view>

#include "sgmp/pack/name_table.hpp"

namespace sgmp {

enum class Sides { Walls, Periodic };

/// walls, periodic.
const NameTable<Sides, 2>& sides_names();
std::string_view to_string(Sides sides);
std::optional<Sides> parse_sides(std::string_view text);

/// How many times across the periodic cell the largest sphere must fit. Every pair search
/// in the cell (reach ≤ 2·r_max plus a skin below r_max) then reaches less than half a
/// period, so the nearest image of a pair is the pair, and each pair is met once.
inline constexpr double kPeriodicCellDiameters = 4.0;

/// The rule a largest diameter breaks in the periodic cell of side `cell` (the text after
/// "--sides periodic: "), or an empty string when it fits kPeriodicCellDiameters times.
std::string periodic_cell_rule(double largest_diameter, double cell);

}  // namespace sgmp
