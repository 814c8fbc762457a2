#pragma once
/// @file sphere_values.hpp
/// One value per sphere, for pictures coloured by structure (`sgmp render --colour z`,
/// `--colour local-phi`):
///
///  - the contact number Z_i(δ) = #{ j ≠ i : |c_i − c_j| − r_i − r_j ≤ δ·d }, d the mean
///    diameter (sphere pairs only, as Z(δ) of local_structure.hpp; walls and floor are
///    not counted), found on the kd-tree (neighbour_index.hpp) within r_i + r_max + δ·d;
///    with periodic sides, minimum-image pairs (periodic_images.hpp);
///  - the Voronoi (radical) local packing fraction φ_i of voronoi.hpp, for every centre,
///    in the container capped one mean diameter above the highest sphere top (cells at the
///    free surface reach the cap).
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::metrics {

/// Z_i(δ) of every sphere, δ = `gap_over_d` ≥ 0, as doubles.
std::vector<double> sphere_contact_numbers(const std::vector<Particle>& particles,
                                           const Container& container, double gap_over_d);

/// φ_i of every sphere in `container` (throws as voronoi_local_phi does).
std::vector<double> sphere_local_phi(const std::vector<Particle>& particles,
                                     const Container& container);

}  // namespace sgmp::metrics
