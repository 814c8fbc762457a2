#pragma once
/// @file dump_format.hpp
/// LAMMPS / LIGGGHTS `dump custom` text files, read strictly.
///
///     ITEM: TIMESTEP / <step>
///     ITEM: NUMBER OF ATOMS / <n>
///     ITEM: BOX BOUNDS <flags> / 3 lines "lo hi"
///     ITEM: ATOMS id type x y z radius ...   (columns by label)
///
/// Columns are found by label: `id`, position `x y z` (or unwrapped `xu yu zu`), and
/// `radius` or `diameter`; other columns are ignored. When a file holds several
/// snapshots the last complete one is returned: a final snapshot cut short by the end of
/// the file (a dump still being written, or a stopped run), even in the middle of a line,
/// is skipped when an earlier one is complete. An error followed by further lines, or in
/// the only snapshot, rejects the file. The timestep and box are recorded in the metadata
/// (`timestep`, `dump_box`); a `bin` column, if present, gives the colour bins and a `species`
/// column the species; velocity columns `vx vy vz`, when all three are present, give
/// `velocity_rms`, the root mean square speed √(Σ|vᵢ|²/N) in the dump's units (a DEM pour's kinetic
/// energy per particle is m·velocity_rms²/2). Errors name source:line and the reason.
///
/// The writer gives one snapshot, `ITEM: ATOMS id type x y z radius bin` (and `species`
/// when the pack has species), with the box
/// bounds `ff ff ff` of the container up to the top (pack_extent.hpp), types by size mode
/// (atom_types.hpp), the header's `timestep` or 0, and numbers in shortest round-trip text.
/// The format has no place for provenance: use the data or XYZ format to keep it.

#include <istream>
#include <ostream>
#include <string>

#include "sgmp/pack/pack.hpp"

namespace sgmp {

Pack read_dump_custom(std::istream& in, const std::string& source);

void write_dump_custom(std::ostream& out, const Pack& pack);

}  // namespace sgmp
