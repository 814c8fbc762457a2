#pragma once
/// @file pack_origin.hpp
/// Moving a pack so that its container's corner is the origin, for tools that ignore a
/// box's `Origin` (ASE's LAMMPS writer, some viewers): every centre and the container move
/// by the same vector s = −(x_min, floor, z_min), so every distance, gap and overlap is
/// unchanged and the container becomes [0, x_max − x_min] × [0, …) × [0, z_max − z_min].
#include "sgmp/pack/pack.hpp"

namespace sgmp {

/// Moves `pack` as above and returns s. The container is the `container` key's, else the
/// thesis container; the moved one is written back to `container`, and s to
/// `origin_shift` ("sx sy sz", the vector added to every centre).
Vec3 move_corner_to_origin(Pack& pack);

}  // namespace sgmp
