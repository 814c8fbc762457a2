// The particle lines of an extended XYZ frame (xyz_format.hpp): the Properties descriptor's
// columns, and the lines parsed in blocks on several threads with the first error in file
// order, as a line-by-line read would report it.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>
#include <stdexcept>

#include "sgmp/pack/parallel.hpp"
#include "sgmp/pack/xyz_format.hpp"
#include "text_fields.hpp"
#include "xyz_internal.hpp"

namespace sgmp::detail {
namespace {

/// Most columns a particle line may declare in all; far above any real file, and small
/// enough that column positions and the line width never overflow an int.
constexpr std::int64_t kMaxColumns = 10000;

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

}  // namespace

/// `text` in lower case (ASCII), for names compared in any case.
std::string lower_ascii(std::string_view text) {
    std::string out(text);
    for (char& c : out) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
}

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
        const std::string key = lower_ascii(name);
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

}  // namespace sgmp::detail
