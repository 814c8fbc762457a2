#pragma once
/// @file vtk_format.hpp
/// Legacy VTK files (the "# vtk DataFile Version 3.0" specification, ASCII) for ParaView
/// and VTK readers (vtkPolyDataReader):
///
/// - the particles: POLYDATA with one point and one vertex per sphere, point arrays
///   `radius` (double), `id` (vtktypeint64) and `bin` (int), and a field array
///   `provenance` of the header's "key=value" strings (spaces and other bytes outside
///   printable ASCII as %XX, as VTK's own writer encodes strings);
/// - the container (a second file): POLYDATA of the container's 8 corners and 12 edges
///   as lines, the container up to the top of the highest sphere (pack_extent.hpp).
///
/// ParaView draws the spheres with the Point Gaussian representation (scale by `radius`)
/// or the Glyph filter (sphere, scale by `radius`, factor 2 for a unit-diameter glyph).
/// Numbers are shortest round-trip text (std::to_chars).

#include <ostream>

#include "sgmp/pack/pack.hpp"

namespace sgmp {

void write_vtk_particles(std::ostream& out, const Pack& pack);

void write_vtk_container(std::ostream& out, const Pack& pack);

}  // namespace sgmp
