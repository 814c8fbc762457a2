#pragma once
/// @file xyz_format.hpp
/// Extended XYZ pack files, readable by OVITO and ASE:
///
///     N
///     Properties=id:I:1:pos:R:3:radius:R:1:bin:I:1 Lattice="1.25 0 0 0 H 0 0 0 1.25"
///         Origin="-0.625 -0.625 -0.625" pbc="F F F" key=value key="a b" ...   (one line)
///     id x y z radius bin            (N lines)
///
/// A pack with species (a blend, particle.hpp) adds `:species_id:I:1` and its column
/// (`species` is extended XYZ's chemical-symbol column, which ASE reads as elements).
/// The colour bin is called `bin` because OVITO takes a property named `color` as an RGB
/// colour. `Lattice` and `Origin` are the container up to the top of the highest sphere
/// (H = y_top − floor; pack_extent.hpp), so OVITO draws it and imports the header keys as
/// attributes, and ASE gets the cell. They are derived, so the reader does not keep them
/// (nor `Properties` and `pbc`) in the metadata.
///
/// The reader finds columns by the Properties descriptor, names in any case (`Radius`,
/// `POS`), any order, extra columns ignored; `radius` may be replaced by `diameter`, the
/// bin (`bin`, or the older `color`) and `species_id` (1…) are optional, and without a radius or
/// diameter the caller's radius (`ReadOptions::radius`) is used. A bare key (`key` without
/// `=value`, as ASE writes a true flag) is kept as `key=T`. A file may hold several frames one
/// after another; one is returned (ReadOptions::frame, from 1; the last by default). Anything it
/// cannot parse is rejected with source:line and the reason. Numbers are written in shortest
/// round-trip form (std::to_chars), so a pack read back is bit-identical.

#include <istream>
#include <ostream>
#include <string>

#include "sgmp/pack/pack.hpp"
#include "sgmp/pack/read_options.hpp"

namespace sgmp {

/// Writes `pack` as extended XYZ. Provenance keys are written in the metadata's order.
/// Throws std::invalid_argument for a value XYZ cannot hold or a malformed `container`.
void write_xyz(std::ostream& out, const Pack& pack);

/// Reads the last frame. `source` names the input in error messages.
/// Throws InputError for malformed input.
Pack read_xyz(std::istream& in, const std::string& source);

/// Reads the frame `options` asks for, validating every frame of the file.
PackRead read_xyz(std::istream& in, const std::string& source, const ReadOptions& options);

}  // namespace sgmp
