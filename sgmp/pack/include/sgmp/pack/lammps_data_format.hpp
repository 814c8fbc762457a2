#pragma once
/// @file lammps_data_format.hpp
/// LAMMPS / LIGGGHTS data files of spheres (`atom_style sphere`), as `read_data` takes them:
///
///     LAMMPS data file (atom_style sphere) of a sphere pack          (title, ignored)
///     # key=value                                  (one line per provenance key)
///     N atoms
///     T atom types
///     x_min x_max xlo xhi / floor top ylo yhi / z_min z_max zlo zhi
///     Atoms # sphere
///     id type diameter density x y z # bin B [species S]   (N lines; species in blends)
///
/// The box is the container up to the top of the highest sphere (pack_extent.hpp). Numbers
/// are shortest round-trip text (std::to_chars), so a pack read back is bit-identical. The
/// density is 1 (mass per cubed control-volume side), so each mass is the sphere's volume
/// (π/6)d³; LAMMPS reads it, and a DEM set-up sets its own. Atom types number the size
/// modes (`size_modes` in the header: the type of a sphere is the mode whose diameter
/// a_i·`diameter` is nearest to its own, in the listed order), else every type is 1. The
/// colour bin goes in the comment after each atom, which LAMMPS ignores and the reader here
/// takes back. Atom ids must be positive (a LAMMPS rule).

#include <istream>
#include <ostream>
#include <string>

#include "sgmp/pack/pack.hpp"

namespace sgmp {

/// Mass density written for every atom.
inline constexpr double kLammpsDataDensity = 1.0;

/// Writes `pack` as a data file. Throws std::invalid_argument naming the format and the
/// field it cannot carry (an id ≤ 0, or a provenance value with a line break).
void write_lammps_data(std::ostream& out, const Pack& pack);

/// Reads a data file with an `Atoms # sphere` section (columns id type diameter density x
/// y z, optional image flags); `# key=value` lines before the counts become metadata.
/// Throws InputError for malformed input.
Pack read_lammps_data(std::istream& in, const std::string& source);

}  // namespace sgmp
