#pragma once
/// @file read_options.hpp
/// What a caller may ask of a pack reader, and what it learns besides the pack.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/pack.hpp"
#include "sgmp/pack/stated_container.hpp"

namespace sgmp {

struct ReadOptions {
    /// The frame of a multi-frame extended XYZ file, counted from 1; nullopt reads the last.
    std::optional<std::size_t> frame;
    /// Every particle gets this radius: needed for files that carry no radius or diameter
    /// column (species-only files), and replaces the file's radii otherwise.
    std::optional<double> radius;
    /// Threads that parse the particle lines of an extended XYZ file (at least 1). The pack,
    /// and the error of a bad file, do not depend on it.
    unsigned threads = 1;
    /// Keep the file's frame (output_frame.hpp: up_axis, box) instead of turning it y up,
    /// and settle no container (stated_container.hpp): the header as written, or the
    /// particles of a file whose walls the caller knows (a pour's own result).
    bool as_written = false;
    /// The walls stated by the user (`--container`, a manifest's `container` column): the
    /// pack's container, which a container the file states itself must match
    /// (stated_container.hpp). Not applied when `as_written`.
    std::optional<StatedContainer> container{};
};

struct PackRead {
    Pack pack;
    /// The frame returned (from 1) and how many frames the file holds.
    std::size_t frame = 1;
    std::size_t frames = 1;
    /// The most digits after the decimal point of any coordinate or radius in the frame
    /// (for "1.5e-05", 6), so 0.5·10^-decimals bounds each number's rounding; nullopt when
    /// the reader does not track it.
    std::optional<int> decimals;
    /// Things the reader decided that the user should hear of, one line each (the front
    /// ends print them as warnings): an extended XYZ whose `container` key disagrees with
    /// its Lattice/Origin cell (the key is kept).
    std::vector<std::string> warnings;
    /// The box of a LAMMPS dump or data file as a container (walls at its x and z bounds,
    /// the floor at its lowest y): taken as the container only when the spheres reach it
    /// (stated_container.hpp); nullopt for other formats.
    std::optional<Container> file_box{};
};

}  // namespace sgmp
