#include "sgmp/pack/dump_format.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "sgmp/pack/geometry.hpp"
#include "text_fields.hpp"

namespace sgmp {
namespace {

/// Column indices of the ATOMS section, found by label.
struct DumpColumns {
    int id = -1;
    std::array<int, 3> position{-1, -1, -1};
    int radius = -1;
    int diameter = -1;
    int bin = -1;
    int species = -1;
    std::array<int, 3> velocity{-1, -1, -1};  // all three, or none used
    std::size_t width = 0;
};

DumpColumns parse_atom_labels(const std::vector<std::string_view>& labels,
                              const LineReader& reader) {
    DumpColumns columns;
    columns.width = labels.size();
    const std::array<std::array<std::string_view, 2>, 3> position_labels{
        {{"x", "xu"}, {"y", "yu"}, {"z", "zu"}}};
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const auto label = labels[i];
        const int index = static_cast<int>(i);
        if (std::find(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(i), label) !=
            labels.begin() + static_cast<std::ptrdiff_t>(i)) {  // the last would silently win
            throw reader.error("ATOMS section names '" + std::string(label) + "' twice");
        }
        for (int axis = 0; axis < 3; ++axis) {
            if (label == std::array<std::string_view, 3>{"vx", "vy", "vz"}[axis]) {
                columns.velocity[axis] = index;
            }
        }
        if (label == "id") {
            columns.id = index;
        } else if (label == "radius") {
            columns.radius = index;
        } else if (label == "diameter") {
            columns.diameter = index;
        } else if (label == "bin") {
            columns.bin = index;
        } else if (label == "species") {
            columns.species = index;
        }
        for (std::size_t axis = 0; axis < 3; ++axis) {
            if (label == position_labels[axis][0] ||
                (label == position_labels[axis][1] && columns.position[axis] < 0)) {
                columns.position[axis] = index;
            }
        }
    }
    const std::array<const char*, 3> axis_names{"x", "y", "z"};
    for (std::size_t axis = 0; axis < 3; ++axis) {
        if (columns.position[axis] < 0) {
            throw reader.error(std::string("ATOMS section lacks the '") + axis_names[axis] +
                               "' column (scaled coordinates are not accepted)");
        }
    }
    if (std::count(columns.velocity.begin(), columns.velocity.end(), -1) != 0) {
        columns.velocity = {-1, -1, -1};  // a speed needs all three components
    }
    if (columns.id < 0) {
        throw reader.error("ATOMS section lacks the 'id' column");
    }
    detail::check_one_size_column(columns.radius >= 0, columns.diameter >= 0, "ATOMS section",
                                  reader);
    if (columns.radius < 0 && columns.diameter < 0) {
        throw reader.error("ATOMS section lacks a 'radius' or 'diameter' column");
    }
    return columns;
}

std::string expect_item(LineReader& reader, std::string_view item) {
    std::string line;
    if (!reader.next(line)) {
        throw reader.error("file ends where 'ITEM: " + std::string(item) + "' was expected");
    }
    const std::string prefix = "ITEM: " + std::string(item);
    if (line.rfind(prefix, 0) != 0) {
        throw reader.error("expected '" + prefix + "', found '" + line + "'");
    }
    return line.substr(prefix.size());
}

std::string expect_line(LineReader& reader, const char* what) {
    std::string line;
    if (!reader.next(line)) {
        throw reader.error(std::string("file ends where ") + what + " was expected");
    }
    return line;
}

std::int64_t expect_integer(LineReader& reader, const char* what) {
    const std::string line = expect_line(reader, what);
    const auto fields = detail::split_fields(line);
    const auto value = fields.size() == 1 ? detail::parse_integer(fields[0]) : std::nullopt;
    if (!value || *value < 0) {
        throw reader.error(std::string(what) + " must be a non-negative integer, found '" + line +
                           "'");
    }
    return *value;
}

double field_number(std::string_view field, const char* label, const LineReader& reader) {
    const auto value = detail::parse_double(field);
    if (!value) {
        throw reader.error(std::string("column '") + label + "' holds '" + std::string(field) +
                           "', which is not a number");
    }
    return *value;
}

/// The three "lo hi" lines after BOX BOUNDS, checked, as "xlo xhi ylo yhi zlo zhi" in the
/// file's own digits.
std::string read_box_bounds(LineReader& reader) {
    std::string box;
    for (int axis = 0; axis < 3; ++axis) {
        const std::string line = expect_line(reader, "a box bounds line");
        const auto fields = detail::split_fields(line);
        const auto lo = fields.size() >= 2 ? detail::parse_double(fields[0]) : std::nullopt;
        const auto hi = fields.size() >= 2 ? detail::parse_double(fields[1]) : std::nullopt;
        if (!lo || !hi) {
            throw reader.error("box bounds line must start with two numbers 'lo hi', found '" +
                               line + "'");
        }
        if (!std::isfinite(*lo) || !std::isfinite(*hi) || !(*lo <= *hi)) {
            throw reader.error("box bounds '" + line + "' must be finite with lo <= hi");
        }
        box.append(axis > 0 ? " " : "").append(fields[0]).append(" ").append(fields[1]);
    }
    return box;
}

/// A simulation box is not a container (stated_container.hpp): the walls come only from
/// words after the BOX BOUNDS flags, "container x_min x_max z_min z_max floor", as
/// `sgmp convert` writes them (LAMMPS and OVITO read the first three flags only).
void set_stated_container(const std::vector<std::string_view>& flags,
                          const std::string& bounds_item, const LineReader& reader, Pack& pack) {
    if (flags.size() <= 3 || flags[3] != "container") {
        return;
    }
    if (flags.size() != 9) {
        throw reader.error("BOX BOUNDS '" + bounds_item +
                           "': 'container' must be followed by five numbers x_min x_max "
                           "z_min z_max floor");
    }
    std::string walls;
    for (std::size_t i = 4; i < flags.size(); ++i) {
        walls.append(i > 4 ? " " : "").append(flags[i]);
    }
    try {
        pack.metadata.set("container", Container::parse(walls).to_string());
    } catch (const std::invalid_argument& error) {
        throw reader.error(error.what());
    }
}

/// One snapshot, from the line after "ITEM: TIMESTEP".
Pack read_snapshot(LineReader& reader) {
    Pack pack;
    const std::int64_t step = expect_integer(reader, "the timestep");
    expect_item(reader, "NUMBER OF ATOMS");
    const std::int64_t count = expect_integer(reader, "the number of atoms");
    const std::string bounds_item = expect_item(reader, "BOX BOUNDS");  // the views below need it
    const auto flags = detail::split_fields(bounds_item);
    // "pp ff pp": periodic x and z (LAMMPS' boundary p f p), the sides of a periodic cell.
    const bool periodic = flags.size() >= 3 && flags[0] == "pp" && flags[2] == "pp";
    const std::string box = read_box_bounds(reader);
    const std::string labels_text = expect_item(reader, "ATOMS");
    const auto labels = detail::split_fields(labels_text);
    const DumpColumns columns = parse_atom_labels(labels, reader);
    pack.metadata.set_integer("timestep", step);
    pack.metadata.set("dump_box", box);
    set_stated_container(flags, bounds_item, reader, pack);
    if (periodic) {
        pack.metadata.set("sides", "periodic");
        if (flags[1] == "pp") {  // fully periodic: no floor, the box's y extent kept
            const auto bounds = detail::split_fields(box);  // xlo xhi ylo yhi zlo zhi
            pack.metadata.set("periodic_y", std::string(bounds[2]) + ' ' + std::string(bounds[3]));
        }
    }
    // The count is only a claim until the lines arrive (see read_xyz_lines).
    pack.particles.reserve(static_cast<std::size_t>(std::min<std::int64_t>(count, 1 << 16)));
    detail::ParticleValidator validator;
    std::string line;
    std::vector<std::string_view> fields;
    double speed_squared_sum = 0.0;
    for (std::int64_t i = 0; i < count; ++i) {
        if (!reader.next(line)) {
            throw reader.error("file ends after " + std::to_string(i) + " of " +
                               std::to_string(count) + " atom lines of timestep " +
                               std::to_string(step));
        }
        detail::split_fields(line, fields);
        if (fields.size() != columns.width) {
            throw reader.error("expected " + std::to_string(columns.width) +
                               " columns as labelled, found " + std::to_string(fields.size()));
        }
        Particle p;
        const auto id = detail::parse_integer(fields[columns.id]);
        if (!id) {
            throw reader.error("column 'id' holds '" + std::string(fields[columns.id]) +
                               "', which is not an integer");
        }
        p.id = *id;
        const std::array<const char*, 3> names{"x", "y", "z"};
        for (int axis = 0; axis < 3; ++axis) {
            p.center[axis] = field_number(fields[columns.position[axis]], names[axis], reader);
        }
        p.radius = columns.radius >= 0
                       ? field_number(fields[columns.radius], "radius", reader)
                       : 0.5 * field_number(fields[columns.diameter], "diameter", reader);
        if (columns.bin >= 0) {
            const auto bin = detail::parse_bin(fields[columns.bin]);
            if (!bin) {
                throw reader.error("column " + detail::bin_error(fields[columns.bin]));
            }
            p.color = *bin;
        }
        if (columns.species >= 0) {
            const auto species = detail::parse_integer(fields[columns.species]);
            if (!species || *species < 1 || *species > kMaxSpecies) {
                throw reader.error(
                    "column 'species' holds '" + std::string(fields[columns.species]) +
                    "', which is not an integer in [1, " + std::to_string(kMaxSpecies) + "]");
            }
            p.species = static_cast<int>(*species);
        }
        if (columns.velocity[0] >= 0) {
            const std::array<const char*, 3> velocity_names{"vx", "vy", "vz"};
            for (int axis = 0; axis < 3; ++axis) {
                const double v =
                    field_number(fields[columns.velocity[axis]], velocity_names[axis], reader);
                if (!std::isfinite(v)) {
                    throw reader.error(std::string("column '") + velocity_names[axis] +
                                       "' holds '" + std::string(fields[columns.velocity[axis]]) +
                                       "', which is not a finite number");
                }
                speed_squared_sum += v * v;
            }
        }
        validator.check(p, reader);
        pack.particles.push_back(p);
    }
    if (columns.velocity[0] >= 0 && count > 0) {
        pack.metadata.set_number("velocity_rms",
                                 std::sqrt(speed_squared_sum / static_cast<double>(count)));
    }
    return pack;
}

}  // namespace

namespace detail {

Pack read_dump_lines(LineReader& reader) {
    std::optional<Pack> last;
    std::string line;
    while (reader.next(line)) {
        if (is_blank(line)) {
            continue;
        }
        if (line.rfind("ITEM: TIMESTEP", 0) != 0) {
            throw reader.error("expected 'ITEM: TIMESTEP', found '" + line + "'");
        }
        if (!last) {
            last = read_snapshot(reader);
            continue;
        }
        try {
            last = read_snapshot(reader);
        } catch (const InputError&) {
            // A later snapshot cut short by the end of the file (a dump still being
            // written, or a stopped run): the last complete one stands. Cut short means
            // the file ended where the snapshot wanted another line, or its last line has
            // no line break (cut inside it). Any other error (a bad value such as `nan` in
            // a whole last line, an error with lines after it) is a malformed file: the
            // snapshot it spoils is not hidden behind an earlier one.
            const bool cut_short =
                reader.ran_out() || (reader.at_end() && reader.last_line_unterminated());
            if (!cut_short) {
                throw;
            }
            break;
        }
    }
    if (!last) {
        throw InputError(reader.source(), reader.line_number(), "empty file: no snapshot");
    }
    last->metadata.set("source_format", "dump custom");
    return std::move(*last);
}

}  // namespace detail

Pack read_dump_custom(std::istream& in, const std::string& source) {
    LineReader reader(in, source);
    return detail::read_dump_lines(reader);
}

}  // namespace sgmp
