#pragma once
/// @file xyz_format.hpp
/// Extended XYZ pack files, readable by OVITO and ASE:
///
///     N
///     Properties=id:I:1:pos:R:3:radius:R:1:color:I:1 pbc="F F F" key=value key="a b" ...
///     id x y z radius color            (N lines)
///
/// The reader finds columns by the Properties descriptor (any order, extra columns
/// ignored; `radius` may be replaced by `diameter`, `color` is optional), and rejects
/// anything it cannot parse with source:line and the reason. Numbers are written in
/// shortest round-trip form, so a pack read back is bit-identical.

#include <istream>
#include <ostream>
#include <string>

#include "sgmp/pack/pack.hpp"

namespace sgmp {

/// Writes `pack` as extended XYZ. Provenance keys are written in the metadata's order.
void write_xyz(std::ostream& out, const Pack& pack);

/// Reads one extended XYZ frame. `source` names the input in error messages.
/// Throws InputError for malformed input.
Pack read_xyz(std::istream& in, const std::string& source);

}  // namespace sgmp
