#pragma once
/// @file stated_container.hpp
/// No container is ever guessed: the one rule that settles a pack's walls when it is read.
///
/// A pack's container (walls at x_min, x_max, z_min, z_max, a floor, no lid; geometry.hpp)
/// comes, in this order, from
/// 1. a statement of the user: `--container "x_min x_max z_min z_max floor"` or a
///    manifest's `container` column (the same five numbers as the header key, parsed by
///    `Container::parse`); it must agree with a container the file states itself;
/// 2. the file's own statement: the extended XYZ header key `container`, a data file's
///    `# container=` comment, a dump's `container` words after its BOX BOUNDS flags (both
///    written by `sgmp convert`);
/// 3. a LAMMPS dump's or data file's own box, only when its spheres reach it: the
///    outermost sphere keeps at most `kBoxReachOverD`·d of clearance beyond contact from
///    every side and from the floor (periodic axes are not walls). A simulation box is not
///    a container: in LAMMPS and LIGGGHTS the walls are usually fixes inside a larger box.
/// Otherwise the file is refused. The container settled must hold every centre.
///
/// The clearance of a face is that of its nearest sphere, c = minᵢ (distance of sphere i's
/// surface from the face), over the mean diameter d: for the side x_min,
/// c = minᵢ (xᵢ − rᵢ − x_min) / d; for the floor, minᵢ (yᵢ − rᵢ − floor) / d. The box is taken
/// when c ≤ kBoxReachOverD at every face (exactly at the threshold is taken).
///
/// `settle_container` records where the walls came from in the header key `container_from`
/// (`box`, or the statement's name such as `--container`; a container from the file's own
/// header adds nothing), so a file written from the pack says what its container is.

#include <optional>
#include <string>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/pack.hpp"

namespace sgmp {

/// The largest clearance beyond contact, over d, that a file's box may keep from the
/// outermost spheres at a side or the floor and still be taken as the container.
inline constexpr double kBoxReachOverD = 0.05;

/// A container stated by the user, and how it was stated (for messages and
/// `container_from`): "--container", "manifest.csv:4".
struct StatedContainer {
    Container walls;
    std::string by;
};

/// The face of a box farthest from its nearest sphere.
struct BoxClearance {
    double gap_over_d = 0.0;  ///< that face's clearance beyond contact, over the mean d
    std::string face;         ///< "x_min", "x_max", "z_min", "z_max" or "floor"
};

/// The largest clearance of the faces of `box` (its sides, unless `box.periodic`, and its
/// floor), each face's clearance that of its nearest sphere, over `mean_d`. For an empty
/// list, 0 at the floor.
BoxClearance largest_box_clearance(const std::vector<Particle>& particles, const Container& box,
                                   double mean_d);

/// The index of the first particle whose centre lies outside `walls` (x outside
/// [x_min, x_max] or z outside [z_min, z_max] unless periodic, or y below the floor), or
/// nullopt when the container holds every centre.
std::optional<std::size_t> first_centre_outside(const std::vector<Particle>& particles,
                                                const Container& walls);

/// True when two containers are the same to 10⁻⁹ of their size (text round trips and
/// unit conversions leave the last digits).
bool same_container(const Container& a, const Container& b);

/// Settles `pack.metadata`'s `container` (and `container_from`) by the rule above.
/// `file_box` is the box of a LAMMPS dump or data file (nullopt for other formats, whose
/// container is their header's or, lacking one, the testbed's). Throws InputError naming
/// `source` when the box is not reached and nothing states the walls, when a statement
/// contradicts the file's own container, or when the container leaves out a centre.
void settle_container(Pack& pack, const std::optional<StatedContainer>& stated,
                      const std::optional<Container>& file_box, const std::string& source);

}  // namespace sgmp
