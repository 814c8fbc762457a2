#include "sgmp/pack/bounded_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "sgmp/pack/input_error.hpp"

namespace sgmp {
namespace {

/// Closes the descriptor when the read ends, however it ends.
class Descriptor {
  public:
    explicit Descriptor(int fd) : fd_(fd) {}
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor() {
        if (fd_ >= 0) {
            ::close(fd_);
        }
    }
    [[nodiscard]] int get() const { return fd_; }

  private:
    int fd_;
};

std::string too_large(std::uint64_t size, bool at_least, std::uint64_t cap,
                      const std::string& what) {
    if (at_least) {
        return "more than " + std::to_string(size) + " bytes, the cap on " + what;
    }
    return std::to_string(size) + " bytes, more than the cap of " + std::to_string(cap) +
           " bytes on " + what;
}

}  // namespace

std::uint64_t effective_cap(std::uint64_t cap) {
    const char* text = std::getenv("SGMP_MAX_FILE_BYTES");
    if (text == nullptr || *text == '\0') {
        return cap;
    }
    char* end = nullptr;
    errno = 0;
    const unsigned long long value = std::strtoull(text, &end, 10);
    if (errno != 0 || *end != '\0' || value == 0 || value >= cap) {
        return cap;
    }
    return value;
}

std::string read_bounded_file(const std::filesystem::path& path, std::uint64_t cap,
                              const std::string& what) {
    const std::string source = path.string();
    cap = effective_cap(cap);
    const Descriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    if (fd.get() < 0) {
        throw InputError(source, 0,
                         std::string("cannot open for reading: ") + std::strerror(errno));
    }
    struct stat status {};
    if (::fstat(fd.get(), &status) != 0) {
        throw InputError(source, 0, std::string("cannot read: ") + std::strerror(errno));
    }
    if (S_ISDIR(status.st_mode)) {
        throw InputError(source, 0, "is a directory, not a file");
    }
    // A regular file states its size: refused before a byte is read (a sparse file too).
    if (S_ISREG(status.st_mode) && static_cast<std::uint64_t>(status.st_size) > cap) {
        throw InputError(source, 0,
                         too_large(static_cast<std::uint64_t>(status.st_size), false, cap, what));
    }
    std::string text;
    if (S_ISREG(status.st_mode)) {
        text.reserve(static_cast<std::size_t>(status.st_size));
    }
    char chunk[65536];
    while (true) {
        const ::ssize_t got = ::read(fd.get(), chunk, sizeof chunk);
        if (got < 0) {
            if (errno == EINTR) {
                continue;
            }
            throw InputError(source, 0, std::string("read error: ") + std::strerror(errno));
        }
        if (got == 0) {
            break;
        }
        // A device or pipe has no size: the read stops one chunk past the cap.
        if (text.size() + static_cast<std::size_t>(got) > cap) {
            throw InputError(source, 0, too_large(cap, true, cap, what));
        }
        text.append(chunk, static_cast<std::size_t>(got));
    }
    return text;
}

}  // namespace sgmp
