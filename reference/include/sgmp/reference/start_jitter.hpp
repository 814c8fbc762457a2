#pragma once
/// @file start_jitter.hpp
/// Breaking the symmetry of a starting arrangement. A DEM pour keeps an exact symmetry for
/// ever: a single column of spheres at x = z = 0 lands as a vertical tower that never
/// topples. Moving each sphere horizontally by a small random offset (uniform in a disk of
/// radius `amplitude`) lets it fall as real spheres would.

#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"
#include "sgmp/pack/random.hpp"

namespace sgmp::reference {

/// Moves each centre (in order) by a random horizontal offset of length ≤ `amplitude`,
/// kept only when the sphere stays inside the container's walls and overlaps no other
/// sphere; otherwise up to nine more offsets are tried, then the centre stays where it was.
/// Returns how many spheres moved.
std::size_t jitter_horizontally(std::vector<Vec3>& centers, double radius, double amplitude,
                                const Container& container, Random& random);

}  // namespace sgmp::reference
