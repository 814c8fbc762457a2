#pragma once
/// @file synthetic_packs.hpp
/// Packs with answers known in advance, for tests and the benchmark: perfect lattices cut
/// to a box, jittered lattices and uniform random (overlapping) centres.

#include <cstdint>
#include <string>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/pack.hpp"

namespace sgmp::testing {

enum class Lattice { simple_cubic, bcc, fcc };

/// Spheres of diameter d touching their nearest neighbours on `lattice`, with every centre
/// inside `box` (lattice origin at box.lo + offset).
Pack lattice_pack(Lattice lattice, double d, const Box& box, const Vec3& offset = Vec3::Zero());

/// `count` spheres of the sizing-rule diameter on an FCC lattice whose nearest-neighbour
/// distance is `spacing`·d, each centre displaced by up to ±jitter·d per axis (seeded),
/// filling the thesis container from the floor upwards, layer by layer.
Pack jittered_fcc_pack(std::size_t count, double spacing, double jitter, std::uint64_t seed);

/// `count` centres uniform in `box` (overlaps allowed), radius d/2.
Pack uniform_pack(std::size_t count, double d, const Box& box, std::uint64_t seed);

}  // namespace sgmp::testing
