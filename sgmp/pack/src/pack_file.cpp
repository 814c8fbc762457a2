#include "sgmp/pack/pack_file.hpp"

#include <boost/iostreams/filter/gzip.hpp>
#include <boost/iostreams/filtering_stream.hpp>
#include <fstream>

#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/xyz_format.hpp"
#include "text_fields.hpp"

namespace sgmp {
namespace {

bool starts_with_gzip_magic(std::istream& in) {
    const int first = in.get();
    const int second = in.get();
    in.clear();
    in.seekg(0);
    return first == 0x1f && second == 0x8b;
}

Pack read_detected(std::istream& in, const std::string& source) {
    detail::LineReader reader(in, source);
    std::string line;
    std::size_t blanks = 0;
    while (reader.next(line) && detail::is_blank(line)) {
        ++blanks;
    }
    if (reader.line_number() == blanks && detail::is_blank(line)) {
        throw InputError(source, 0, "empty file");
    }
    const bool is_dump = line.rfind("ITEM:", 0) == 0;
    reader.put_back(line);
    if (is_dump) {
        return detail::read_dump_lines(reader);
    }
    if (blanks > 0) {
        throw InputError(source, 1, "blank line where the particle count was expected");
    }
    return detail::read_xyz_lines(reader);
}

}  // namespace

Pack read_pack_file(const std::filesystem::path& path) {
    const std::string source = path.string();
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw InputError(source, 0, "cannot open for reading");
    }
    try {
        if (starts_with_gzip_magic(file)) {
            boost::iostreams::filtering_istream decompressed;
            decompressed.push(boost::iostreams::gzip_decompressor());
            decompressed.push(file);
            try {
                return read_detected(decompressed, source);
            } catch (const InputError&) {
                // Decompression failures surface as a bad stream, not as gzip_error.
                if (decompressed.bad()) {
                    throw InputError(source, 0, "corrupt or truncated gzip data");
                }
                throw;
            }
        }
        return read_detected(file, source);
    } catch (const boost::iostreams::gzip_error& error) {
        throw InputError(source, 0, std::string("corrupt or truncated gzip data: ") + error.what());
    }
}

void write_pack_file(const std::filesystem::path& path, const Pack& pack, bool overwrite) {
    write_file_atomically(path, overwrite, [&](std::ostream& out) { write_xyz(out, pack); });
}

}  // namespace sgmp
