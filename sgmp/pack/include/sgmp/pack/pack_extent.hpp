#pragma once
/// @file pack_extent.hpp
/// Where a pack sits: its container (from the `container` header key, else the testbed's)
/// and its top, the height of the highest sphere's top, y_top = max_i (y_i + r_i). Writers
/// of other formats use these for box bounds and cells.

#include <array>
#include <optional>
#include <string>
#include <utility>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/pack.hpp"

namespace sgmp {

/// The container recorded in the header (`container="x_min x_max z_min z_max floor"`), or
/// the testbed's when the key is absent; periodic when `sides=periodic`. Throws
/// std::invalid_argument for a malformed key.
Container container_of(const Pack& pack);

/// max_i (y_i + r_i), never below the floor; for an empty pack the floor plus the
/// container's width in x (a cube), so a box is never flat.
double top_of(const Pack& pack, const Container& container);

/// The box other formats are given: the container from the floor up to `top_of`, widened
/// where needed so that it holds every centre (a pack from elsewhere may not sit in the
/// testbed's container; tools such as LAMMPS drop atoms whose centre is outside the box).
/// For a testbed pack this is exactly the container up to the top. A pack in an output
/// frame (output_frame.hpp) has its written box in the `box` key; that box is returned.
/// Throws std::invalid_argument for a malformed `box`.
Box container_box(const Pack& pack);

/// Which written axes (x, y, z) are periodic: x and z for periodic sides, x and y for a
/// pack written z up (`up_axis=z`), none with walls, all three for a fully periodic cell
/// read from elsewhere (`periodic_y`). LAMMPS' `boundary` flags, extended XYZ's `pbc` and
/// a dump's BOX BOUNDS follow from it.
std::array<bool, 3> periodic_axes(const Pack& pack);

/// A fully periodic cell (a LAMMPS dump "pp pp pp", an extended XYZ pbc="T T T") has no
/// floor: its y extent "YLO YHI" is kept as the key `periodic_y`, in the testbed's frame,
/// and is the box's y extent in every format written; the metrics refuse such a pack.
/// nullopt when the key is absent; throws std::invalid_argument when malformed.
std::optional<std::pair<double, double>> periodic_y_extent(const Pack& pack);
std::string periodic_y_text(double lo, double hi);

}  // namespace sgmp
