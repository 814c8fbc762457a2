#include "sgmp/pack/pack_file.hpp"

#include <array>
#include <boost/iostreams/concepts.hpp>
#include <boost/iostreams/filter/gzip.hpp>
#include <boost/iostreams/filtering_stream.hpp>
#include <boost/iostreams/operations.hpp>
#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/dump_format.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "sgmp/pack/lammps_data_format.hpp"
#include "sgmp/pack/output_frame.hpp"
#include "sgmp/pack/stated_container.hpp"
#include "sgmp/pack/vtk_format.hpp"
#include "sgmp/pack/vtp_format.hpp"
#include "sgmp/pack/xyz_format.hpp"
#include "text_fields.hpp"

namespace sgmp {
namespace {

/// A stream buffer that yields `prefix`, then what is left in `rest`, a block at a time:
/// a file whose first line was read to detect its format, read again from its start.
class PrefixedBuffer : public std::streambuf {
  public:
    PrefixedBuffer(std::string prefix, std::streambuf& rest)
        : prefix_(std::move(prefix)), rest_(rest) {
        setg(prefix_.data(), prefix_.data(), prefix_.data() + prefix_.size());
    }

  protected:
    int_type underflow() override {
        if (gptr() < egptr()) {
            return traits_type::to_int_type(*gptr());
        }
        const std::streamsize got = rest_.sgetn(block_.data(), block_.size());
        if (got <= 0) {
            return traits_type::eof();
        }
        setg(block_.data(), block_.data(), block_.data() + got);
        return traits_type::to_int_type(*gptr());
    }

  private:
    std::string prefix_;
    std::streambuf& rest_;
    std::array<char, 65536> block_{};
};

/// A decompression bomb guard (after Apache POI's ZipSecureFile): once a gzip stream has
/// inflated past kInflationFloor bytes, it may not hold more than kMostInflation times the
/// compressed bytes read so far. Pack text compresses about 3× (the reference pours and a
/// 10⁵-sphere SGMP pack: 2.6–2.9×); text that compresses 100× is repetition, not spheres,
/// and would cost memory in proportion to what it inflates to. A tripped guard ends the
/// stream and is reported by the caller (an exception inside the filter chain would be
/// swallowed by the stream).
constexpr std::uint64_t kInflationFloor = std::uint64_t{4} << 20;
constexpr std::uint64_t kMostInflation = 100;

struct Inflation {
    std::uint64_t inflated = 0;
    std::uint64_t compressed = 0;
    bool tripped = false;
};

class InflationGuard : public boost::iostreams::multichar_input_filter {
  public:
    InflationGuard(std::streambuf& file, std::shared_ptr<Inflation> state)
        : file_(&file), state_(std::move(state)) {}

    template <class Source>
    std::streamsize read(Source& source, char* s, std::streamsize n) {
        if (state_->tripped) {
            return -1;
        }
        const std::streamsize got = boost::iostreams::read(source, s, n);
        if (got > 0) {
            state_->inflated += static_cast<std::uint64_t>(got);
            const auto at = file_->pubseekoff(0, std::ios::cur, std::ios::in);
            if (at > 0) {
                state_->compressed = static_cast<std::uint64_t>(at);
            }
            if (state_->inflated > kInflationFloor &&
                state_->inflated > kMostInflation * state_->compressed) {
                state_->tripped = true;
                return -1;
            }
        }
        return got;
    }

  private:
    std::streambuf* file_;
    std::shared_ptr<Inflation> state_;
};

void refuse_inflation(const Inflation& state, const std::string& source) {
    if (state.tripped) {
        throw InputError(source, 0,
                         "gzip data inflating more than " + std::to_string(kMostInflation) +
                             " times its compressed size (" + std::to_string(state.inflated) +
                             " bytes from " + std::to_string(state.compressed) +
                             "): repetition, not a pack (pack text compresses about 3 times); "
                             "decompress it (gunzip) to read it as plain text");
    }
}

bool starts_with_gzip_magic(std::istream& in) {
    const int first = in.get();
    const int second = in.get();
    in.clear();
    in.seekg(0);
    return first == 0x1f && second == 0x8b;
}

void refuse_frame(const std::string& source, const ReadOptions& options, const char* format) {
    if (options.frame) {
        throw InputError(source, 0,
                         std::string("a frame can be chosen in extended XYZ files only; this is "
                                     "a ") +
                             format + " file");
    }
}

/// The box a dump (`dump_box`) or data file (`data_box`) recorded, "xlo xhi ylo yhi zlo
/// zhi", as a container: walls at its x and z bounds, the floor at its lowest y.
std::optional<Container> recorded_box(const Pack& pack, const char* key) {
    const auto text = pack.metadata.get(key);
    if (!text) {
        return std::nullopt;
    }
    std::istringstream in(*text);
    std::array<double, 6> b{};
    for (double& v : b) {
        in >> v;
    }
    if (in.fail()) {
        return std::nullopt;
    }
    Container box;
    box.x_min = b[0];
    box.x_max = b[1];
    box.floor = b[2];
    box.z_min = b[4];
    box.z_max = b[5];
    return box;
}

PackRead single(Pack pack, const ReadOptions& options, const char* box_key) {
    if (options.radius) {
        for (auto& p : pack.particles) {
            p.radius = *options.radius;
        }
    }
    PackRead read;
    read.file_box = recorded_box(pack, box_key);
    read.pack = std::move(pack);
    return read;
}

PackRead read_detected(std::istream& in, const std::string& source, bool data_name,
                       const ReadOptions& options) {
    LineReader reader(in, source);
    std::string line;
    std::size_t blanks = 0;
    while (reader.next(line) && detail::is_blank(line)) {
        ++blanks;
    }
    if (reader.line_number() == blanks && detail::is_blank(line)) {
        throw InputError(source, 0, "empty file");
    }
    if (line.rfind("# vtk DataFile", 0) == 0 || line.rfind("<?xml", 0) == 0 ||
        line.rfind("<VTKFile", 0) == 0) {  // a VTK file (legacy or XML), as `convert` writes
        throw InputError(source, reader.line_number(),
                         "a VTK file: VTK is an output format only (for ParaView); read the "
                         "extended XYZ, dump or data file it was converted from");
    }
    const bool is_dump = line.rfind("ITEM:", 0) == 0;
    const bool is_data = !is_dump && (data_name || line.rfind("LAMMPS data file", 0) == 0);
    reader.put_back(line);
    if (is_dump) {
        refuse_frame(source, options, "dump");
        return single(detail::read_dump_lines(reader), options, "dump_box");
    }
    if (is_data) {
        refuse_frame(source, options, "LAMMPS data");
        // The data reader numbers lines itself: hand it the line read and the rest of the
        // stream as they come (the whole text was once copied twice into memory first).
        std::string first;
        reader.next(first);
        PrefixedBuffer rest(first + '\n', *in.rdbuf());
        std::istream again(&rest);
        return single(read_lammps_data(again, source), options, "data_box");
    }
    if (blanks > 0) {
        throw InputError(source, 1, "blank line where the particle count was expected");
    }
    return detail::read_xyz_lines(reader, options);
}

/// The pack as the file has it, in the file's frame (output_frame.hpp).
PackRead read_pack_file_as_written(const std::filesystem::path& path, const ReadOptions& options) {
    const std::string source = path.string();
    const bool data_name = format_from_extension(path) == PackFormat::lammps_data;
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw InputError(source, 0, "cannot open for reading");
    }
    try {
        if (starts_with_gzip_magic(file)) {
            const auto inflation = std::make_shared<Inflation>();
            boost::iostreams::filtering_istream decompressed;
            decompressed.push(InflationGuard(*file.rdbuf(), inflation));
            decompressed.push(boost::iostreams::gzip_decompressor());
            decompressed.push(file);
            try {
                PackRead read = read_detected(decompressed, source, data_name, options);
                refuse_inflation(*inflation, source);  // a frame cut short would pass
                return read;
            } catch (const InputError&) {
                refuse_inflation(*inflation, source);
                // Decompression failures surface as a bad stream, not as gzip_error.
                if (decompressed.bad()) {
                    throw InputError(source, 0, "corrupt or truncated gzip data");
                }
                throw;
            }
        }
        return read_detected(file, source, data_name, options);
    } catch (const boost::iostreams::gzip_error& error) {
        throw InputError(source, 0, std::string("corrupt or truncated gzip data: ") + error.what());
    }
}

}  // namespace

Pack read_pack_file(const std::filesystem::path& path) {
    return read_pack_file(path, ReadOptions{}).pack;
}

PackRead read_pack_file(const std::filesystem::path& path, const ReadOptions& options) {
    PackRead read = read_pack_file_as_written(path, options);
    if (!options.as_written) {
        to_internal_frame(read.pack);
        settle_container(read.pack, options.container, read.file_box, path.string());
    }
    return read;
}

void write_pack_file(const std::filesystem::path& path, const Pack& pack, bool overwrite) {
    write_file_atomically(path, overwrite, [&](std::ostream& out) { write_xyz(out, pack); });
}

std::filesystem::path container_file_for(const std::filesystem::path& path) {
    std::filesystem::path stem = path;
    const std::string ending = stem.extension() == ".vtp" ? ".vtp" : ".vtk";
    if (stem.extension() == ending) {
        stem.replace_extension();
    }
    stem += ".container" + ending;
    return stem;
}

namespace {

/// The text of one format, produced in memory first, so a pack the format cannot carry
/// fails before any file is touched.
std::string format_text(const Pack& pack, PackFormat format) {
    std::ostringstream out;
    switch (format) {
        case PackFormat::xyz:
        case PackFormat::xyz_gz:
            write_xyz(out, pack);
            break;
        case PackFormat::lammps_data:
            write_lammps_data(out, pack);
            break;
        case PackFormat::lammps_dump:
            write_dump_custom(out, pack);
            break;
        case PackFormat::vtk:
            write_vtk_particles(out, pack);
            break;
        case PackFormat::vtp:
            write_vtp_particles(out, pack);
            break;
    }
    return out.str();
}

void check_name(const std::filesystem::path& path, PackFormat format) {
    const bool gz_name = path.filename().string().ends_with(".gz");
    if (format == PackFormat::xyz_gz && !gz_name) {
        throw std::invalid_argument(path.string() +
                                    ": format xyz.gz needs a file name ending in .gz");
    }
    if (format != PackFormat::xyz_gz && gz_name) {
        throw std::invalid_argument(path.string() + ": format " + std::string(to_string(format)) +
                                    " is not compressed; a name ending in .gz is for xyz.gz");
    }
}

void write_text(const std::filesystem::path& path, const std::string& text, bool overwrite) {
    write_file_atomically(path, overwrite, [&](std::ostream& out) { out << text; });
}

}  // namespace

void write_pack_as(const std::filesystem::path& path, const Pack& pack, PackFormat format,
                   const WriteOptions& options) {
    check_name(path, format);
    check_writable(path, options.overwrite);
    const std::string text = format_text(pack, format);
    if (!has_container_file(format)) {
        write_text(path, text, options.overwrite);
        return;
    }
    const std::filesystem::path container = container_file_for(path);
    check_writable(container, options.overwrite);
    std::ostringstream box;
    if (format == PackFormat::vtp) {
        write_vtp_container(box, pack);
    } else {
        write_vtk_container(box, pack);
    }
    const std::string container_text = box.str();
    // The pair is published whole or not at all: a lone container makes a re-run refuse,
    // and particles beside another pack's container would be read in the wrong box.
    write_files_atomically({{container, [&](std::ostream& out) { out << container_text; }},
                            {path, [&](std::ostream& out) { out << text; }}},
                           options.overwrite);
}

}  // namespace sgmp
