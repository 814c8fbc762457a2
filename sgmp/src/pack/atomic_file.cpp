#include "sgmp/pack/atomic_file.hpp"

#include <unistd.h>

#include <boost/iostreams/filter/gzip.hpp>
#include <boost/iostreams/filtering_stream.hpp>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace sgmp {
namespace fs = std::filesystem;

namespace {

std::runtime_error path_error(const fs::path& path, const std::string& reason) {
    return std::runtime_error(path.string() + ": " + reason);
}

fs::path sibling_temporary(const fs::path& target, const char* kind) {
    const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    return parent /
           ("." + target.filename().string() + "." + kind + "-" + std::to_string(::getpid()));
}

bool ends_with_gz(const fs::path& path) {
    return path.extension() == ".gz";
}

/// Moves `from` to `to`. Without `overwrite` this is a hard link plus unlink, which
/// fails rather than replace a file that appeared in the meantime.
void move_into_place(const fs::path& from, const fs::path& to, bool overwrite) {
    if (overwrite) {
        std::error_code error;
        fs::rename(from, to, error);
        if (error) {
            throw path_error(to, "cannot rename the finished file into place: " + error.message());
        }
        return;
    }
    if (::link(from.c_str(), to.c_str()) != 0) {
        const int code = errno;
        throw path_error(to, code == EEXIST ? "exists; pass --force to replace it"
                                            : std::string("cannot create: ") + std::strerror(code));
    }
    fs::remove(from);
}

}  // namespace

void check_writable(const fs::path& target, bool overwrite) {
    if (target.empty() || target.filename().empty()) {
        throw path_error(target, "not a file name");
    }
    std::error_code error;
    if (!overwrite && fs::exists(target, error)) {
        throw path_error(target, "exists; pass --force to replace it");
    }
    const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    fs::create_directories(parent, error);
    if (error || !fs::is_directory(parent)) {
        throw path_error(target, "cannot create its directory " + parent.string() +
                                     (error ? ": " + error.message() : ""));
    }
    if (::access(parent.c_str(), W_OK) != 0) {
        throw path_error(target, "directory " + parent.string() + " is not writable");
    }
}

void write_file_atomically(const fs::path& target, bool overwrite,
                           const std::function<void(std::ostream&)>& produce) {
    check_writable(target, overwrite);
    const fs::path temporary = sibling_temporary(target, "tmp");
    try {
        std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
        if (!file) {
            throw path_error(target, std::string("cannot create a file in its directory: ") +
                                         std::strerror(errno));
        }
        if (ends_with_gz(target)) {
            boost::iostreams::filtering_ostream compressed;
            compressed.push(boost::iostreams::gzip_compressor(boost::iostreams::gzip_params(9)));
            compressed.push(file);
            produce(compressed);
            compressed.reset();  // flushes the gzip trailer into `file`
        } else {
            produce(file);
        }
        file.flush();
        if (!file) {
            throw path_error(temporary, "write failed (disk full?)");
        }
        file.close();
        move_into_place(temporary, target, overwrite);
    } catch (...) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw;
    }
}

void write_directory_atomically(const fs::path& target, bool overwrite,
                                const std::function<void(const fs::path&)>& produce) {
    check_writable(target, overwrite);
    const fs::path temporary = sibling_temporary(target, "tmp");
    std::error_code ignored;
    fs::remove_all(temporary, ignored);
    fs::create_directories(temporary);
    try {
        produce(temporary);
        if (fs::exists(target)) {
            if (!overwrite) {
                throw path_error(target, "exists; pass --force to replace it");
            }
            const fs::path old = sibling_temporary(target, "old");
            fs::remove_all(old, ignored);
            fs::rename(target, old);
            fs::rename(temporary, target);
            fs::remove_all(old, ignored);
        } else {
            fs::rename(temporary, target);
        }
    } catch (...) {
        fs::remove_all(temporary, ignored);
        throw;
    }
}

}  // namespace sgmp
