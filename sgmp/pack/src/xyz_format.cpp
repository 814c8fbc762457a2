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

namespace sgmp {
namespace {

constexpr std::string_view kProperties = "id:I:1:pos:R:3:radius:R:1:bin:I:1";
/// The species of a blend (particle.hpp). Not `species`: in extended XYZ that is the
/// chemical-symbol column (ASE reads it as element symbols and fails on numbers).
constexpr std::string_view kSpeciesProperty = ":species_id:I:1";
/// ASE reads (and writes) the `masses` column as the atoms' masses.
constexpr std::string_view kMassProperty = ":masses:R:1";

/// Most columns a particle line may declare in all; far above any real file, and small
/// enough that column positions and the line width never overflow an int.
constexpr std::int64_t kMaxColumns = 10000;

bool needs_quotes(const std::string& value) {
    return value.empty() || value.find_first_of(" \t=") != std::string::npos;
}

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

/// `text` in lower case (ASCII), for names compared in any case.
std::string lower(std::string_view text) {
    std::string out(text);
    for (char& c : out) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
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

Columns parse_properties(const std::string& descriptor, bool have_radius,
                         const LineReader& reader) {
    std::vector<std::string> parts;
    std::size_t pos = 0;
    while (pos <= descriptor.size()) {
        const std::size_t colon = descriptor.find(':', pos);
        parts.push_back(
            descriptor.substr(pos, colon == std::string::npos ? std::string::npos : colon - pos));
        if (colon == std::string::npos) {
            break;
        }
        pos = colon + 1;
    }
    if (parts.size() % 3 != 0) {
        throw reader.error("Properties='" + descriptor + "' is not a list of name:type:count");
    }
    Columns columns;
    std::set<std::string> names;
    for (std::size_t i = 0; i < parts.size(); i += 3) {
        const std::string& name = parts[i];
        const std::string key = lower(name);
        if (!names.insert(key).second) {  // the last would silently win
            throw reader.error("Properties names '" + name + "' twice");
        }
        const auto count = detail::parse_integer(parts[i + 2]);
        if (!count || *count < 1 || *count > kMaxColumns - columns.width) {
            throw reader.error("Properties entry '" + name + "' has count '" + parts[i + 2] +
                               "'; a count must be a positive integer and all entries together "
                               "at most " +
                               std::to_string(kMaxColumns) + " columns");
        }
        const auto expect = [&](std::int64_t wanted) {
            if (*count != wanted) {
                throw reader.error("Properties entry '" + name + "' must have " +
                                   std::to_string(wanted) + " column(s)");
            }
        };
        if (key == "id") {
            expect(1);
            columns.id = columns.width;
        } else if (key == "pos") {
            expect(3);
            columns.x = columns.width;
        } else if (key == "radius") {
            expect(1);
            columns.radius = columns.width;
        } else if (key == "diameter") {
            expect(1);
            columns.diameter = columns.width;
        } else if (key == "bin" || key == "color") {
            expect(1);
            if (columns.color >= 0) {
                throw reader.error("Properties holds both 'bin' and 'color': give one");
            }
            columns.color = columns.width;
        } else if (key == "species_id") {
            expect(1);
            columns.species = columns.width;
        }
        columns.width += static_cast<int>(*count);
    }
    if (columns.x < 0) {
        throw reader.error("Properties lacks the 'pos' column");
    }
    detail::check_one_size_column(columns.radius >= 0, columns.diameter >= 0, "Properties", reader);
    if (columns.radius < 0 && columns.diameter < 0 && !have_radius) {
        throw reader.error(
            "Properties lacks a 'radius' or 'diameter' column; give the radius (--radius R)");
    }
    return columns;
}

/// A line of the source, for errors found away from the reader (parsing in parallel).
struct LineAt {
    const std::string& source;
    std::size_t line;
    [[nodiscard]] InputError error(const std::string& reason) const {
        return InputError(source, line, reason);
    }
};

double number_field(std::string_view field, const char* what, const LineAt& at) {
    const auto value = detail::parse_double(field);
    if (!value) {
        throw at.error(std::string(what) + " '" + std::string(field) + "' is not a number");
    }
    return *value;
}

std::int64_t integer_field(std::string_view field, const char* what, const LineAt& at) {
    const auto value = detail::parse_integer(field);
    if (!value) {
        throw at.error(std::string(what) + " '" + std::string(field) + "' is not an integer");
    }
    return *value;
}

/// One particle line; `decimals` grows to the most decimals of its numbers. Its values are
/// checked here (check_particle_values); its id is checked against the others later.
Particle parse_particle(std::string_view line, const Columns& columns, std::int64_t index,
                        const ReadOptions& options, int& decimals, const LineAt& at,
                        std::vector<std::string_view>& fields) {
    detail::split_fields(line, fields);
    if (static_cast<int>(fields.size()) != columns.width) {
        throw at.error("expected " + std::to_string(columns.width) + " columns, found " +
                       std::to_string(fields.size()));
    }
    Particle particle;
    particle.id = columns.id >= 0 ? integer_field(fields[columns.id], "id", at) : index + 1;
    for (int k = 0; k < 3; ++k) {
        particle.center[k] = number_field(fields[columns.x + k], "coordinate", at);
        decimals = std::max(decimals, detail::decimals_of(fields[columns.x + k]));
    }
    if (options.radius) {
        particle.radius = *options.radius;
    } else if (columns.radius >= 0) {
        particle.radius = number_field(fields[columns.radius], "radius", at);
        decimals = std::max(decimals, detail::decimals_of(fields[columns.radius]));
    } else {
        particle.radius = 0.5 * number_field(fields[columns.diameter], "diameter", at);
        decimals = std::max(decimals, detail::decimals_of(fields[columns.diameter]));
    }
    if (columns.color >= 0) {
        const auto bin = detail::parse_bin(fields[columns.color]);
        if (!bin) {
            throw at.error(detail::bin_error(fields[columns.color]));
        }
        particle.color = *bin;
    }
    if (columns.species >= 0) {
        const std::int64_t species = integer_field(fields[columns.species], "species_id", at);
        if (species < 1 || species > kMaxSpecies) {
            throw at.error("species_id " + std::to_string(species) + " is not in [1, " +
                           std::to_string(kMaxSpecies) + "]");
        }
        particle.species = static_cast<int>(species);
    }
    detail::check_particle_values(particle, at.source, at.line);
    return particle;
}

/// Lines of one block: line k is text[end[k − 1], end[k]).
struct LineBlock {
    std::string text;
    std::vector<std::size_t> end;
    std::size_t first_line = 0;  ///< number of line 0 in the source
    [[nodiscard]] std::size_t size() const { return end.size(); }
    [[nodiscard]] std::string_view line(std::size_t k) const {
        const std::size_t begin = k == 0 ? 0 : end[k - 1];
        return std::string_view(text).substr(begin, end[k] - begin);
    }
};

/// What parsing one chunk of a block found.
struct ChunkParse {
    int decimals = 0;
    std::size_t failed = 0;  ///< line (in the block) of `error`
    std::optional<InputError> error;
};

/// Parses lines [begin, end) of `block` into particles[k] for line k (`particles` is the
/// block's first slot; `first_index` the frame index of its line 0).
ChunkParse parse_chunk(const LineBlock& block, std::size_t begin, std::size_t end,
                       std::int64_t first_index, const Columns& columns, const ReadOptions& options,
                       const std::string& source, Particle* particles) {
    ChunkParse parse;
    std::vector<std::string_view> fields;
    for (std::size_t k = begin; k < end; ++k) {
        const LineAt at{source, block.first_line + k};
        try {
            particles[k] =
                parse_particle(block.line(k), columns, first_index + static_cast<std::int64_t>(k),
                               options, parse.decimals, at, fields);
        } catch (const InputError& error) {
            parse.failed = k;
            parse.error = error;
            break;
        }
    }
    return parse;
}

/// The `count` particle lines of a frame into `read`. Blocks of lines are gathered from the
/// reader, parsed on options.threads threads in chunks of fixed size, and their ids checked
/// in line order, so the error reported is the first in the file whatever the thread count,
/// as in a line-by-line read.
void read_particle_lines(LineReader& reader, std::int64_t count, const Columns& columns,
                         const ReadOptions& options, PackRead& read) {
    // A block holds at most kBlockLines lines and stops growing once it holds kBlockBytes,
    // so the text buffered at once is below kBlockBytes + kMaxLineBytes (24 MiB) however
    // long the lines (a gzip bomb of 15 MiB lines), not kBlockLines · kMaxLineBytes.
    constexpr std::int64_t kBlockLines = 1 << 16;
    constexpr std::size_t kBlockBytes = std::size_t{8} << 20;
    constexpr std::size_t kChunkLines = 4096;
    std::vector<Particle>& particles = read.pack.particles;
    detail::ParticleValidator ids;
    LineBlock block;
    std::string line;
    int decimals = 0;
    while (static_cast<std::int64_t>(particles.size()) < count) {
        const auto done = static_cast<std::int64_t>(particles.size());
        block.text.clear();
        block.end.clear();
        block.first_line = reader.line_number() + 1;
        bool ended = false;
        for (std::int64_t k = 0; k < std::min(kBlockLines, count - done); ++k) {
            if (block.text.size() >= kBlockBytes) {
                break;  // long lines: the block is full before its line count
            }
            if (!reader.next(line)) {
                ended = true;
                break;
            }
            block.text += line;
            block.end.push_back(block.text.size());
        }
        const std::size_t lines = block.size();
        particles.resize(particles.size() + lines);
        Particle* const first = particles.data() + done;
        std::vector<ChunkParse> chunks((lines + kChunkLines - 1) / kChunkLines);
        parallel_for(options.threads, chunks.size(), [&](std::size_t c) {
            chunks[c] = parse_chunk(block, c * kChunkLines, std::min(lines, (c + 1) * kChunkLines),
                                    done, columns, options, reader.source(), first);
        });
        std::size_t good = lines;  // lines before the first error
        for (const ChunkParse& chunk : chunks) {
            decimals = std::max(decimals, chunk.decimals);
            if (chunk.error) {
                good = chunk.failed;
                break;
            }
        }
        for (std::size_t k = 0; k < good; ++k) {
            ids.check_id(first[k].id, reader.source(), block.first_line + k);
        }
        for (const ChunkParse& chunk : chunks) {
            if (chunk.error) {
                throw *chunk.error;
            }
        }
        if (ended) {
            throw reader.error("file ends after " + std::to_string(particles.size()) + " of " +
                               std::to_string(count) + " particle lines");
        }
    }
    read.decimals = decimals;
}

/// Header keys the writer derives; the reader does not keep them (names in any case).
bool is_derived_key(const std::string& key) {
    const std::string name = lower(key);
    return name == "properties" || name == "pbc" || name == "lattice" || name == "origin";
}

/// A `Lattice` (9 numbers) or `Origin` (3) must be a cell: finite numbers, and a Lattice's
/// diagonal ≥ 0 (ASE and OVITO read it). Returns its numbers (none for another key).
std::vector<double> cell_numbers(const std::string& key, const std::string& value,
                                 const LineReader& reader) {
    const std::string name = lower(key);
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

std::string lattice_text(const Box& box) {
    const Vec3 side = box.hi - box.lo;
    return format_number(side.x()) + " 0 0 0 " + format_number(side.y()) + " 0 0 0 " +
           format_number(side.z());
}

/// The `pbc` of a pack: periodic sides are x and z, or x and y when written z up.
std::string pbc_text(const Pack& pack) {
    const auto axes = periodic_axes(pack);
    std::string text;
    for (const bool periodic : axes) {
        text += text.empty() ? "" : " ";
        text += periodic ? "T" : "F";
    }
    return text;
}

/// The cell written as Lattice and Origin: the container from the floor to the top (not
/// widened: a pack's own cell), or the output frame's box (output_frame.hpp).
Box written_xyz_box(const Pack& pack) {
    if (pack.metadata.contains("box") || pack.metadata.contains("periodic_y")) {
        return container_box(pack);
    }
    const Container c = container_of(pack);
    return c.box_up_to(top_of(pack, c));
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
    std::optional<Columns> columns;
    std::vector<double> lattice;
    std::vector<double> origin;
    std::string pbc;
    for (auto& [key, value] : parse_comment(line, reader)) {
        if (lower(key) == "properties") {
            columns = parse_properties(value, options.radius.has_value(), reader);
        } else if (!is_derived_key(key)) {
            read.pack.metadata.set(key, std::move(value));
        } else if (lower(key) == "lattice") {
            lattice = cell_numbers(key, value, reader);
        } else if (lower(key) == "origin") {
            origin = cell_numbers(key, value, reader);
        } else if (lower(key) == "pbc") {
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
    read_particle_lines(reader, *count, *columns, options, read);
    return read;
}

/// Appends `value` to `line` as std::to_chars writes it (shortest round trip for doubles,
/// the same text as format_number).
template <class T>
char* append(char* line, char* end, T value) {
    return std::to_chars(line, end, value).ptr;
}

/// The particle lines "id x y z radius bin [species] [mass]", formatted into a block of memory
/// that is written whenever it fills: one stream call per block instead of eleven per particle.
void write_particle_lines(std::ostream& out, const std::vector<Particle>& particles, bool species,
                          const std::vector<double>* densities) {
    constexpr std::size_t kBlock = 1 << 16;
    constexpr std::size_t kLongestLine = 8 * 32;  // eight numbers of at most 24 characters each
    std::vector<char> block(kBlock + kLongestLine);
    char* const begin = block.data();
    char* const end = begin + block.size();
    char* at = begin;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Particle& p = particles[i];
        at = append(at, end, p.id);
        for (const double value : {p.center.x(), p.center.y(), p.center.z(), p.radius}) {
            *at++ = ' ';
            at = append(at, end, value);
        }
        *at++ = ' ';
        at = append(at, end, p.color);
        if (species) {
            *at++ = ' ';
            at = append(at, end, p.species);
        }
        if (densities != nullptr) {
            *at++ = ' ';
            at = append(at, end, sphere_mass((*densities)[i], p.radius));
        }
        *at++ = '\n';
        if (static_cast<std::size_t>(at - begin) >= kBlock) {
            out.write(begin, at - begin);
            at = begin;
        }
    }
    out.write(begin, at - begin);
}

}  // namespace

void write_xyz(std::ostream& out, const Pack& pack) {
    const Box box = written_xyz_box(pack);
    out << pack.particles.size() << '\n';
    const bool species = has_species(pack.particles);
    const auto densities = particle_densities(pack);  // a mass column where they are stated
    out << "Properties=" << kProperties << (species ? kSpeciesProperty : "")
        << (densities ? kMassProperty : "") << " Lattice=\"" << lattice_text(box) << "\" Origin=\""
        << format_number(box.lo.x()) << ' ' << format_number(box.lo.y()) << ' '
        << format_number(box.lo.z()) << "\" pbc=\"" << pbc_text(pack) << "\"";
    if (!pack.metadata.contains("container")) {  // the walls, always (stated_container.hpp)
        out << " container=\"" << container_of(pack).to_string() << '"';
    }
    for (const auto& [key, value] : pack.metadata.entries()) {
        if (is_derived_key(key)) {
            continue;
        }
        check_header_entry(key, value);
        out << ' ' << key << '=';
        if (needs_quotes(value)) {
            out << '"' << value << '"';
        } else {
            out << value;
        }
    }
    out << '\n';
    write_particle_lines(out, pack.particles, species, densities ? &*densities : nullptr);
}

Pack read_xyz(std::istream& in, const std::string& source) {
    return read_xyz(in, source, ReadOptions{}).pack;
}

PackRead read_xyz(std::istream& in, const std::string& source, const ReadOptions& options) {
    LineReader reader(in, source);
    return detail::read_xyz_lines(reader, options);
}

namespace detail {

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
