#include "sgmp/pack/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <boost/iostreams/categories.hpp>
#include <boost/iostreams/filter/gzip.hpp>
#include <boost/iostreams/filtering_stream.hpp>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <ios>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <vector>

#include "sgmp/pack/host_name.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "temporary_names.hpp"

namespace sgmp {
namespace fs = std::filesystem;

namespace {

/// zlib level of every .gz the testbed writes. Measured on a 10⁵-sphere pack (8.7 MB of
/// text): level 1 compresses in 0.08 s to 3.37 MB, level 6 in 0.41 s to 3.07 MB, level 9 in
/// 1.08 s to 3.03 MB. Level 9 was half of a whole `sgmp pack` run; level 1 costs 11 % in size.
constexpr int kGzipLevel = 1;

std::runtime_error path_error(const fs::path& path, const std::string& reason) {
    return std::runtime_error(path.string() + ": " + reason);
}

/// The writer's process id of a temporary named `.NAME.tmp-PID.HOST` by this host, or 0
/// for any other name (another host's temporary, or not a temporary).
pid_t local_writer_of(const std::string& name) {
    constexpr std::string_view marker = ".tmp-";
    const auto at = name.rfind(marker);
    if (name.empty() || name.front() != '.' || at == std::string::npos || at == 0) {
        return 0;
    }
    const std::string_view rest = std::string_view(name).substr(at + marker.size());
    long long pid = 0;
    const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), pid);
    if (error != std::errc() || pid <= 0 || pid > std::numeric_limits<pid_t>::max() ||
        std::string_view(end, static_cast<std::size_t>(rest.data() + rest.size() - end)) !=
            "." + host_name()) {
        return 0;
    }
    return static_cast<pid_t>(pid);
}

bool ends_with_gz(const fs::path& path) {
    return path.extension() == ".gz";
}

/// A file descriptor as a Boost.Iostreams sink. A failed write throws at once (a short
/// count would make the gzip compressor retry for ever when the disk is full).
class DescriptorSink {
  public:
    using char_type = char;
    using category = boost::iostreams::sink_tag;

    /// `failure` receives the message of a failed write.
    DescriptorSink(int fd, const fs::path* target, std::string* failure)
        : fd_(fd), target_(target), failure_(failure) {}

    std::streamsize write(const char* data, std::streamsize size) {
        std::streamsize done = 0;
        while (done < size) {
            const ssize_t wrote = ::write(fd_, data + done, static_cast<std::size_t>(size - done));
            if (wrote < 0 && errno == EINTR) {
                continue;
            }
            if (wrote <= 0) {
                *failure_ = target_->string() + ": write failed: " +
                            (wrote < 0 ? std::strerror(errno) : "no space written");
                throw std::ios_base::failure(*failure_);
            }
            done += wrote;
        }
        return size;
    }

  private:
    int fd_;
    const fs::path* target_;
    std::string* failure_;
};

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
        if (code == EEXIST) {
            throw FileExists(to);
        }
        throw path_error(to, std::string("cannot create: ") + std::strerror(code));
    }
    std::error_code ignored;  // the target is in place; a temporary left over is harmless
    fs::remove(from, ignored);
}

}  // namespace

fs::path sibling_temporary(const fs::path& target, const char* kind) {
    return parent_of(target) / ("." + target.filename().string() + "." + kind + "-" +
                                std::to_string(::getpid()) + "." + host_name());
}

fs::path parent_of(const fs::path& target) {
    return target.parent_path().empty() ? fs::path(".") : target.parent_path();
}

void sync_directory(const fs::path& directory) {
    const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        (void)::fsync(fd);  // some file systems cannot sync a directory; the data is synced
        ::close(fd);
    }
}

int create_exclusive(const fs::path& path) {
    for (int attempt = 0; attempt < 2; ++attempt) {
        const int fd =
            ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST || attempt > 0) {
            return fd;
        }
        // The name holds this process's id, so whatever sits there is a leftover of an
        // earlier process with the same id, or a planted link: removed (a symbolic link
        // itself, never what it points to), then created afresh.
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
    return -1;
}

FileExists::FileExists(const fs::path& path)
    : std::runtime_error(path.string() + ": exists; pass --force to replace it"), path_(path) {}

std::size_t remove_stale_temporaries(const fs::path& directory) {
    std::size_t removed = 0;
    std::error_code error;
    for (fs::directory_iterator entry(directory, error), end; !error && entry != end;
         entry.increment(error)) {
        const pid_t writer = local_writer_of(entry->path().filename().string());
        if (writer > 0 && ::kill(writer, 0) != 0 && errno == ESRCH) {
            std::error_code ignored;
            removed += fs::remove_all(entry->path(), ignored) > 0 ? 1 : 0;
        }
    }
    return removed;
}

void check_writable(const fs::path& target, bool overwrite) {
    if (target.empty() || target.filename().empty()) {
        throw path_error(target, "not a file name");
    }
    std::error_code error;
    if (!overwrite && fs::exists(target, error)) {
        throw FileExists(target);
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

namespace {

/// A temporary beside `target` holding the complete content `produce` wrote, synced to
/// disk; removed when the object ends unless it was renamed into place meanwhile.
class FinishedTemporary {
  public:
    FinishedTemporary(const fs::path& target, const std::function<void(std::ostream&)>& produce);
    ~FinishedTemporary() { remove_temporary(temporary_); }
    FinishedTemporary(const FinishedTemporary&) = delete;
    FinishedTemporary& operator=(const FinishedTemporary&) = delete;
    [[nodiscard]] const fs::path& path() const { return temporary_; }

  private:
    fs::path temporary_;
    std::unique_ptr<TemporaryGuard> guard_;
};

FinishedTemporary::FinishedTemporary(const fs::path& target,
                                     const std::function<void(std::ostream&)>& produce)
    : temporary_(sibling_temporary(target, "tmp")) {
    int fd = -1;
    int open_error = 0;  // errno of open, kept before the guard's unlock can touch errno
    guard_ = std::make_unique<TemporaryGuard>(temporary_, [&] {
        fd = create_exclusive(temporary_);
        open_error = errno;
    });
    if (fd < 0) {
        throw path_error(target, std::string("cannot create a file in its directory: ") +
                                     std::strerror(open_error));
    }
    bool open = true;
    std::string failure;
    try {
        {
            boost::iostreams::filtering_ostream out;
            if (ends_with_gz(target)) {
                out.push(
                    boost::iostreams::gzip_compressor(boost::iostreams::gzip_params(kGzipLevel)));
            }
            out.push(DescriptorSink(fd, &target, &failure), 1 << 16);
            // A failed write stops `produce` at once, as an exception.
            out.exceptions(std::ios::badbit);
            produce(out);
            out.flush();
            out.exceptions(std::ios::goodbit);
            out.reset();  // writes the gzip trailer; a failure there throws from the sink
            if (!failure.empty()) {
                throw std::ios_base::failure(failure);
            }
        }
        if (::fsync(fd) != 0) {
            throw path_error(target,
                             std::string("cannot sync the file to disk: ") + std::strerror(errno));
        }
        open = false;
        if (::close(fd) != 0) {
            throw path_error(target, std::string("write failed: ") + std::strerror(errno));
        }
    } catch (const std::ios_base::failure& error) {
        if (open) {
            ::close(fd);
        }
        remove_temporary(temporary_);
        // The sink's message names the file and the reason; a stream's own says less.
        throw std::runtime_error(
            !failure.empty() ? failure : target.string() + ": write failed: " + error.what());
    } catch (...) {
        if (open) {
            ::close(fd);
        }
        remove_temporary(temporary_);
        throw;
    }
}

/// Renames finished temporaries onto their targets, all or none: before the first rename
/// each existing target gets a hard-linked backup, and when a later rename fails the
/// targets already replaced get their old content back (or are removed when they had
/// none). The caller holds interrupts off (run_uninterrupted), so no signal lands between
/// two renames.
void publish_together(const std::vector<fs::path>& targets,
                      const std::vector<std::unique_ptr<FinishedTemporary>>& files,
                      bool overwrite) {
    std::vector<fs::path> backups(targets.size());
    for (std::size_t i = 0; i < targets.size() && overwrite; ++i) {
        const fs::path backup = sibling_temporary(fs::path(targets[i].string() + ".old"), "tmp");
        if (::link(targets[i].c_str(), backup.c_str()) == 0) {
            backups[i] = backup;
            continue;
        }
        const int code = errno;
        if (code == ENOENT) {
            continue;  // no old file to keep
        }
        // A file system without hard links: a copy; without either, replace nothing rather
        // than risk losing the old file.
        std::error_code copied;
        fs::copy_file(targets[i], backup, copied);
        if (!copied) {
            backups[i] = backup;
            continue;
        }
        std::error_code ignored;
        fs::remove(backup, ignored);
        for (const fs::path& made : backups) {
            fs::remove(made, ignored);
        }
        throw path_error(targets[i], std::string("cannot keep the old file while replacing it: ") +
                                         std::strerror(code));
    }
    std::size_t published = 0;
    try {
        for (; published < targets.size(); ++published) {
            move_into_place(files[published]->path(), targets[published], overwrite);
        }
    } catch (...) {
        std::error_code ignored;
        for (std::size_t i = 0; i < published; ++i) {
            if (!backups[i].empty()) {
                fs::rename(backups[i], targets[i], ignored);
            } else {
                fs::remove(targets[i], ignored);
            }
        }
        for (const fs::path& backup : backups) {
            fs::remove(backup, ignored);
        }
        throw;
    }
    for (const fs::path& backup : backups) {
        std::error_code ignored;
        fs::remove(backup, ignored);
    }
}

}  // namespace

void write_file_atomically(const fs::path& target, bool overwrite,
                           const std::function<void(std::ostream&)>& produce) {
    check_writable(target, overwrite);
    const FinishedTemporary file(target, produce);
    move_into_place(file.path(), target, overwrite);
    sync_directory(parent_of(target));
}

void write_files_atomically(const std::vector<AtomicOutput>& outputs, bool overwrite) {
    std::vector<fs::path> targets;
    for (const AtomicOutput& output : outputs) {
        check_writable(output.target, overwrite);
        targets.push_back(output.target);
    }
    std::vector<std::unique_ptr<FinishedTemporary>> files;
    for (const AtomicOutput& output : outputs) {
        files.push_back(std::make_unique<FinishedTemporary>(output.target, output.produce));
    }
    run_uninterrupted([&] { publish_together(targets, files, overwrite); });
    for (const fs::path& target : targets) {
        sync_directory(parent_of(target));
    }
}

void write_stream_file(const fs::path& path, const std::function<void(std::ostream&)>& produce) {
    // Never through a symbolic link: these files live in directories the testbed made.
    const int fd =
        ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0) {
        throw path_error(path, std::string("cannot write: ") + std::strerror(errno));
    }
    std::string failure;
    try {
        boost::iostreams::filtering_ostream out;
        out.push(DescriptorSink(fd, &path, &failure), 1 << 16);
        out.exceptions(std::ios::badbit);  // a failed write stops `produce` at once
        produce(out);
        out.flush();
        out.exceptions(std::ios::goodbit);
        out.reset();
        if (!failure.empty()) {
            throw std::ios_base::failure(failure);
        }
    } catch (const std::ios_base::failure& error) {
        ::close(fd);
        throw std::runtime_error(
            !failure.empty() ? failure : path.string() + ": write failed: " + error.what());
    } catch (...) {
        ::close(fd);
        throw;
    }
    if (::close(fd) != 0) {
        throw path_error(path, std::string("write failed: ") + std::strerror(errno));
    }
}

void write_text_file(const fs::path& path, const std::string& text) {
    write_stream_file(path, [&](std::ostream& out) { out << text; });
}

std::string read_text_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) {
        throw path_error(path, "cannot read");
    }
    if (!in.is_open()) {
        throw path_error(path, "cannot read");
    }
    return text;
}

ScratchDirectory::ScratchDirectory(const std::string& prefix) {
    std::string pattern =
        (fs::temp_directory_path() / (prefix + "-" + std::to_string(::getpid()) + "-XXXXXX"))
            .string();
    if (::mkdtemp(pattern.data()) == nullptr) {
        throw path_error(fs::temp_directory_path(), "cannot create a scratch directory");
    }
    path_ = pattern;
    guard_ = std::make_unique<TemporaryGuard>(path_);
}

ScratchDirectory::~ScratchDirectory() {
    remove_temporary(path_);
}

}  // namespace sgmp
