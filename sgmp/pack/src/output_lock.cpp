#include "sgmp/pack/output_lock.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include "sgmp/pack/host_name.hpp"

namespace sgmp {
namespace fs = std::filesystem;

namespace {

fs::path lock_path_of(const fs::path& target) {
    const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    return parent / ("." + target.filename().string() + ".lock");
}

/// Locks the whole of `fd` for writing without waiting: true when taken.
bool try_lock(int fd) {
    struct flock lock = {};
    lock.l_type = F_WRLCK;
    lock.l_whence = SEEK_SET;
    return ::fcntl(fd, F_SETLK, &lock) == 0;
}

/// True while `fd` is still the file at `path` (a releasing holder may have removed it
/// between our open and our lock; then the lock guards nothing and is taken again).
bool still_at(int fd, const fs::path& path) {
    struct stat open_file = {};
    struct stat named = {};
    return ::fstat(fd, &open_file) == 0 && ::lstat(path.c_str(), &named) == 0 &&
           open_file.st_dev == named.st_dev && open_file.st_ino == named.st_ino;
}

std::string holder_of(int fd) {
    char text[300] = {};
    const ssize_t got = ::pread(fd, text, sizeof text - 1, 0);
    std::string holder(text, got > 0 ? static_cast<std::size_t>(got) : 0);
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == '\0')) {
        holder.pop_back();
    }
    return holder.empty() ? "unknown" : holder;
}

}  // namespace

OutputLock::OutputLock(const fs::path& target) : path_(lock_path_of(target)) {
    for (int attempt = 0; attempt < 100; ++attempt) {
        // Never through a symbolic link: a link planted at the lock's fixed name would
        // have the holder's line written into whatever it points to.
        const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd < 0 && errno == ELOOP) {
            throw std::runtime_error(target.string() + ": its lock file " + path_.string() +
                                     " is a symbolic link; remove it and run again");
        }
        if (fd < 0) {
            throw std::runtime_error(target.string() + ": cannot create its lock file " +
                                     path_.string() + ": " + std::strerror(errno));
        }
        struct stat opened = {};
        if (::fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode)) {
            ::close(fd);
            throw std::runtime_error(target.string() + ": its lock file " + path_.string() +
                                     " is not a regular file; remove it and run again");
        }
        if (!try_lock(fd)) {
            const int code = errno;
            const std::string holder = holder_of(fd);
            ::close(fd);
            if (code == EACCES || code == EAGAIN) {
                throw std::runtime_error(target.string() +
                                         ": is being written by another process (" + holder + ")");
            }
            throw std::runtime_error(target.string() + ": cannot lock " + path_.string() + ": " +
                                     std::strerror(code));
        }
        if (still_at(fd, path_)) {
            const std::string me = host_name() + " pid " + std::to_string(::getpid()) + "\n";
            if (::ftruncate(fd, 0) == 0) {
                (void)!::pwrite(fd, me.data(), me.size(), 0);  // only for the refusal's text
            }
            fd_ = fd;
            guard_ = std::make_unique<TemporaryGuard>(path_);
            return;
        }
        ::close(fd);
    }
    throw std::runtime_error(target.string() + ": cannot lock " + path_.string() +
                             ": it keeps being replaced");
}

OutputLock::~OutputLock() {
    guard_.reset();
    std::error_code ignored;
    fs::remove(path_, ignored);  // while still locked, so no one holds a removed file
    ::close(fd_);
}

}  // namespace sgmp
