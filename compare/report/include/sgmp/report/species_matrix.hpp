#pragma once
/// @file species_matrix.hpp
/// The per-species verdict matrix of a blend's report: under a header row per count, one
/// row per SGMP mode and DEM class, one mark per per-species row (species_rows.hpp: each
/// species' Z(δ) and Voronoi φ mean, the mixing profile's largest deviation) and how many
/// of them agree. Marks as crossval_render.hpp's. Nothing for packs of equal spheres.
#include <sstream>

#include "sgmp/report/crossval.hpp"

namespace sgmp::report {

/// Appends the section (a heading, a sentence and the table) when any comparison holds
/// per-species rows.
void species_matrix_markdown(std::ostringstream& md, const CrossValidation& cv);

}  // namespace sgmp::report
