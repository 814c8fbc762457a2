// The extended XYZ reader (xyz_format.hpp): frames, the comment line's keys and the
// Lattice/Origin cell; the particle lines are xyz_particles.cpp's, the writer xyz_write.cpp.
#include "sgmp/pack/xyz_format.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <set>
#include <stdexcept>

#include "sgmp/pack/header_entry.hpp"
#include "sgmp/pack/pack_extent.hpp"
#include "sgmp/pack/parallel.hpp"
#include "sgmp/pack/particle_density.hpp"
#include "text_fields.hpp"
#include "xyz_internal.hpp"

namespace sgmp {
namespace {

using detail::lower_ascii;

bool is_identifier(const std::string& word) {
    const auto head_ok = [](char c) {
        return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
    };
    const auto tail_ok = [&](char c) {
        return head_ok(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-';
    };
    return !word.empty() && head_ok(word.front()) &&
           std::all_of(word.begin() + 1, word.end(), tail_ok);
}

/// key=value pairs of the comment line; values may be double-quoted. The header rule of
/// every pack reader applies (detail::HeaderKeys: a bounded number of keys, each once, no
/// control character, UTF-8).
std::vector<std::pair<std::string, std::string>> parse_comment(const std::string& line,
                                                               const LineReader& reader) {
    std::vector<std::pair<std::string, std::string>> pairs;
    detail::HeaderKeys keys;
    const auto add = [&](std::string key, std::string value) {
        keys.add(key, value, reader);
        pairs.emplace_back(std::move(key), std::move(value));
    };
    std::size_t pos = 0;
    while (true) {
        pos = line.find_first_not_of(" \t", pos);
        if (pos == std::string::npos) {
            break;
        }
        const std::size_t eq = line.find('=', pos);
        const std::size_t space = line.find_first_of(" \t", pos);
        if (eq == std::string::npos || (space != std::string::npos && space < eq)) {
            std::string word =
                line.substr(pos, space == std::string::npos ? std::string::npos : space - pos);
            if (!is_identifier(word)) {
                throw reader.error("expected key=value or a bare key in the header, found '" +
                                   word + "'");
            }
            add(std::move(word), "T");  // a bare key is a true flag (ASE)
            pos = space == std::string::npos ? line.size() : space;
            continue;
        }
        std::string key = line.substr(pos, eq - pos);
        std::string value;
        pos = eq + 1;
        if (pos < line.size() && line[pos] == '"') {
            const std::size_t close = line.find('"', pos + 1);
            if (close == std::string::npos) {
                throw reader.error("unterminated quote in the value of '" + key + "'");
            }
            value = line.substr(pos + 1, close - pos - 1);
            pos = close + 1;
        } else {
            const std::size_t end = line.find_first_of(" \t", pos);
            value = line.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
            pos = end == std::string::npos ? line.size() : end;
        }
        add(std::move(key), std::move(value));
    }
    return pairs;
}

/// A `Lattice` (9 numbers) or `Origin` (3) must be a cell: finite numbers, and a Lattice's
/// diagonal ≥ 0 (ASE and OVITO read it). Returns its numbers (none for another key).
std::vector<double> cell_numbers(const std::string& key, const std::string& value,
                                 const LineReader& reader) {
    const std::string name = lower_ascii(key);
    const std::size_t expected = name == "lattice" ? 9 : name == "origin" ? 3 : 0;
    if (expected == 0) {
        return {};
    }
    std::vector<double> numbers;
    const char* p = value.data();
    const char* const last = value.data() + value.size();
    while (p != last) {
        while (p != last && (*p == ' ' || *p == '\t')) {
            ++p;
        }
        double v = 0.0;
        const auto [end, ec] = std::from_chars(p, last, v);
        if (p == last || ec != std::errc()) {
            break;
        }
        numbers.push_back(v);
        p = end;
    }
    const bool finite =
        std::all_of(numbers.begin(), numbers.end(), [](double v) { return std::isfinite(v); });
    if (p != last || numbers.size() != expected || !finite ||
        (expected == 9 && (numbers[0] < 0.0 || numbers[4] < 0.0 || numbers[8] < 0.0))) {
        throw reader.error(key + "=\"" + value + "\" must be " + std::to_string(expected) +
                           " finite numbers" + (expected == 9 ? ", its diagonal >= 0" : ""));
    }
    return numbers;
}

/// The file's own cell as its box (walls at the Lattice's x and z faces, the floor at its
/// lowest y), when the Lattice is an orthogonal box of positive width: a simulation box is
/// not a container, so without a `container` key it is taken only when the spheres reach
/// it (stated_container.hpp); with a key, a container that differs from the cell in x, z or
/// the floor is kept and named in a warning.
void take_cell(const std::vector<double>& lattice, const std::vector<double>& origin,
               PackRead& read) {
    const bool orthogonal = lattice.size() == 9 && lattice[1] == 0.0 && lattice[2] == 0.0 &&
                            lattice[3] == 0.0 && lattice[5] == 0.0 && lattice[6] == 0.0 &&
                            lattice[7] == 0.0 && lattice[0] > 0.0 && lattice[8] > 0.0;
    if (!orthogonal) {
        return;
    }
    const double ox = origin.empty() ? 0.0 : origin[0];
    const double oy = origin.empty() ? 0.0 : origin[1];
    const double oz = origin.empty() ? 0.0 : origin[2];
    const Container cell{ox, ox + lattice[0], oz, oz + lattice[8], oy};
    const auto key = read.pack.metadata.get("container");
    if (read.pack.metadata.contains("box")) {
        return;  // written in an output frame: the cell is the turned box (output_frame.hpp)
    }
    if (!key) {
        read.file_box = cell;
        return;
    }
    Container stated;
    try {
        stated = Container::parse(*key);
    } catch (const std::invalid_argument&) {
        return;  // the key's own check reports it where the container is used
    }
    // The same container to a millionth of the cell's size (an ASE file rewrites the
    // numbers with 8 decimals).
    const double tolerance = 1e-6 * (std::abs(lattice[0]) + std::abs(lattice[8]) + std::abs(ox) +
                                     std::abs(oy) + std::abs(oz));
    const bool same = std::abs(stated.x_min - cell.x_min) <= tolerance &&
                      std::abs(stated.x_max - cell.x_max) <= tolerance &&
                      std::abs(stated.z_min - cell.z_min) <= tolerance &&
                      std::abs(stated.z_max - cell.z_max) <= tolerance &&
                      std::abs(stated.floor - cell.floor) <= tolerance;
    if (!same) {
        read.warnings.push_back(
            "container '" + *key +
            "' (x_min x_max z_min z_max floor) is not the Lattice/Origin cell '" +
            cell.to_string() + "'; the container key is used");
    }
}

/// Reads one frame whose count line is `count_line`; the reader stands on that line.
PackRead read_frame(const std::string& count_line, std::size_t frame, const ReadOptions& options,
                    LineReader& reader) {
    const auto fields = detail::split_fields(count_line);
    const auto count = fields.size() == 1 ? detail::parse_integer(fields[0]) : std::nullopt;
    if (!count || *count < 0) {
        throw reader.error(frame == 1
                               ? "expected the particle count, found '" + count_line + "'"
                               : "expected the particle count of frame " + std::to_string(frame) +
                                     " (or the end of the file), found '" + count_line +
                                     "'; are there more particle lines than the frame's count?");
    }
    std::string line;
    if (!reader.next(line)) {
        throw reader.error("file ends before the header line");
    }
    PackRead read;
    read.frame = frame;
    std::optional<detail::Columns> columns;
    std::vector<double> lattice;
    std::vector<double> origin;
    std::string pbc;
    for (auto& [key, value] : parse_comment(line, reader)) {
        if (lower_ascii(key) == "properties") {
            columns = detail::parse_properties(value, options.radius.has_value(), reader);
        } else if (!detail::is_derived_xyz_key(key)) {
            read.pack.metadata.set(key, std::move(value));
        } else if (lower_ascii(key) == "lattice") {
            lattice = cell_numbers(key, value, reader);
        } else if (lower_ascii(key) == "origin") {
            origin = cell_numbers(key, value, reader);
        } else if (lower_ascii(key) == "pbc") {
            pbc = value;
        }
    }
    // Periodic x and z (ASE, OVITO: pbc="T F T") are periodic sides, unless the header
    // says otherwise; a file written z up says so (up_axis) and is turned back later.
    if (!read.pack.metadata.contains("sides") && !read.pack.metadata.contains("up_axis")) {
        const auto flags = detail::split_fields(pbc);
        const auto on = [](std::string_view f) {
            return f == "T" || f == "t" || f == "True" || f == "true" || f == "1";
        };
        if (flags.size() == 3 && on(flags[0]) && on(flags[2])) {
            read.pack.metadata.set("sides", "periodic");
            if (on(flags[1]) && lattice.size() == 9) {  // fully periodic: no floor
                const double oy = origin.size() == 3 ? origin[1] : 0.0;
                read.pack.metadata.set("periodic_y", periodic_y_text(oy, oy + lattice[4]));
            }
        }
    }
    take_cell(lattice, origin, read);
    if (!columns) {
        throw reader.error("header lacks Properties=...");
    }
    // The count is only a claim until the lines arrive: reserve no more than a small
    // block up front, so a short file claiming 10^15 particles fails at its end, not in
    // the allocator.
    read.pack.particles.reserve(static_cast<std::size_t>(std::min<std::int64_t>(*count, 1 << 16)));
    detail::read_particle_lines(reader, *count, *columns, options, read);
    return read;
}

}  // namespace

Pack read_xyz(std::istream& in, const std::string& source) {
    return read_xyz(in, source, ReadOptions{}).pack;
}

PackRead read_xyz(std::istream& in, const std::string& source, const ReadOptions& options) {
    LineReader reader(in, source);
    return detail::read_xyz_lines(reader, options);
}

namespace detail {

bool is_derived_xyz_key(const std::string& key) {
    const std::string name = lower_ascii(key);
    return name == "properties" || name == "pbc" || name == "lattice" || name == "origin";
}

PackRead read_xyz_lines(LineReader& reader, const ReadOptions& options) {
    if (options.frame && *options.frame < 1) {
        throw InputError(reader.source(), 0, "frame 0 does not exist: frames count from 1");
    }
    std::string line;
    if (!reader.next(line) || is_blank(line)) {
        throw InputError(reader.source(), reader.line_number(),
                         "empty file: expected the particle count on line 1");
    }
    std::optional<PackRead> chosen;
    std::size_t frames = 0;
    do {
        if (frames > 0 && is_blank(line)) {
            continue;  // blank lines may follow the last frame
        }
        ++frames;
        PackRead read = read_frame(line, frames, options, reader);
        if (!options.frame || *options.frame == frames) {
            chosen = std::move(read);
        }
    } while (reader.next(line));
    if (!chosen) {
        throw InputError(reader.source(), 0,
                         "frame " + std::to_string(*options.frame) +
                             " does not exist: the file has " + std::to_string(frames) +
                             " frame(s), counted from 1");
    }
    chosen->frames = frames;
    return std::move(*chosen);
}

}  // namespace detail
}  // namespace sgmp
