#pragma once
/// @file output_frame.hpp
/// The frame a pack file is written in, for tools with other conventions. Inside the
/// testbed y is up and lengths are in control-volume sides (the thesis' unit cube).
///
///  - **Up axis z** (LAMMPS, LIGGGHTS, OVITO and most DEM set-ups): each centre
///    c = (x, y, z) is written as R·c = (x, −z, y), R the right-handed turn by +90° about
///    x, which takes the floor's normal +y to +z; the written box is R applied to the
///    container box (pack_extent.hpp), [x_min, x_max] × [−z_max, −z_min] × [floor, top].
///  - **Length scale** L in a named unit: every centre, radius and container number is
///    multiplied by L, so one control-volume side becomes L units (a pack of diameter
///    d = 0.0416 written with L = 0.01 and unit m has spheres of 0.416 mm). A pack already
///    in a unit (`length_scale` L₀) is multiplied by L/L₀. The request's recorded
///    parameters (`diameter`) stay in control-volume sides.
///  - **Density** ρ (LAMMPS data files): the density column, so that a sphere's mass is
///    ρ·(π/6)·diameter³ in the file's units (kg/m³ with metres).
///
/// The file's header records the frame (`up_axis`, `length_scale`, `length_unit`,
/// `particle_density`) and the written box (`box` = "xlo xhi ylo yhi zlo zhi", which every
/// writer uses instead of the container). Reading a file whose header says up_axis=z turns
/// it back (R⁻¹: (x, y, z) → (x, z, −y)) and drops `box`, so y is up inside again; lengths
/// stay in the file's unit (every metric is a ratio of lengths).
#include <optional>
#include <string>

#include "sgmp/pack/pack.hpp"

namespace sgmp {

enum class UpAxis { Y, Z };

struct OutputFrame {
    UpAxis up = UpAxis::Y;
    double length_scale = 1.0;      ///< L, > 0
    std::string length_unit;        ///< the unit L is in; empty: control-volume sides
    std::optional<double> density;  ///< ρ for data files; unset: 1
};

/// `pack` in `frame` as above, ready for any writer.
Pack in_output_frame(const Pack& pack, const OutputFrame& frame);

/// Turns a pack read from a file written with up_axis=z back to y up, and drops `box`;
/// leaves any other pack as it is.
void to_internal_frame(Pack& pack);

}  // namespace sgmp
