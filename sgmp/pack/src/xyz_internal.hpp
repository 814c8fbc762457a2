#pragma once
// What the extended XYZ reader (xyz_format.cpp), its particle lines (xyz_particles.cpp) and
// its writer (xyz_write.cpp) share.

#include <cstdint>
#include <string>
#include <string_view>

#include "sgmp/pack/line_reader.hpp"
#include "sgmp/pack/xyz_format.hpp"

namespace sgmp::detail {

/// Header keys the writer derives (Properties, Lattice, Origin, pbc); the reader does not
/// keep them and the writer does not copy them from the metadata (names in any case).
bool is_derived_xyz_key(const std::string& key);

/// `text` in lower case (ASCII), for names compared in any case.
std::string lower_ascii(std::string_view text);

/// Column positions of the fields we read, found from the Properties descriptor.
struct Columns {
    int id = -1;
    int x = -1;
    int radius = -1;
    int diameter = -1;
    int color = -1;
    int species = -1;
    int width = 0;
};

/// The columns a Properties descriptor declares; with `have_radius` (a radius given to the
/// reader) neither a radius nor a diameter column is needed. Errors name `reader`'s line.
Columns parse_properties(const std::string& descriptor, bool have_radius, const LineReader& reader);

/// The `count` particle lines of a frame into `read`. Blocks of lines are gathered from the
/// reader, parsed on options.threads threads in chunks of fixed size, and their ids checked
/// in line order, so the error reported is the first in the file whatever the thread count,
/// as in a line-by-line read.
void read_particle_lines(LineReader& reader, std::int64_t count, const Columns& columns,
                         const ReadOptions& options, PackRead& read);

}  // namespace sgmp::detail
