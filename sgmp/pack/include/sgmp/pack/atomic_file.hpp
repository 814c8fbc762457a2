#pragma once
/// @file atomic_file.hpp
/// All-or-nothing outputs: content goes to a temporary beside the target and is renamed
/// into place only when complete, so a crash or error never leaves a half-written file.

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>

#include "sgmp/pack/interrupt.hpp"

namespace sgmp {

/// Fails unless `target` can be written: its parent directory exists (or can be created)
/// and, without `overwrite`, the target does not exist. Throws std::runtime_error
/// "<path>: <reason>" so callers can refuse before any expensive work.
void check_writable(const std::filesystem::path& target, bool overwrite);

/// Writes a file atomically: `produce` writes to a stream on a temporary file in the
/// same directory, which is flushed and renamed to `target`. The temporary is removed if
/// `produce` throws. Content is gzip-compressed when `target` ends in ".gz".
void write_file_atomically(const std::filesystem::path& target, bool overwrite,
                           const std::function<void(std::ostream&)>& produce);

/// Writes `text` to `path`, replacing it: for files inside a directory that is itself
/// being built atomically (write_directory_atomically) or a scratch directory. Throws
/// std::runtime_error "<path>: cannot write".
void write_text_file(const std::filesystem::path& path, const std::string& text);

/// The whole content of a file; throws std::runtime_error "<path>: cannot read".
std::string read_text_file(const std::filesystem::path& path);

/// A fresh directory under the system's temporary directory, named PREFIX-PID-XXXXXX,
/// removed with everything in it when the object ends (and on interrupt, through
/// interrupt.hpp's TemporaryGuard). For scratch work whose results are copied out.
class ScratchDirectory {
  public:
    explicit ScratchDirectory(const std::string& prefix);
    ~ScratchDirectory();
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
    std::unique_ptr<TemporaryGuard> guard_;
};

/// Replaces directory `target` atomically: `produce` fills a fresh temporary directory
/// beside it, which then takes the target's place (an existing target is removed only
/// with `overwrite`, and only after `produce` succeeded).
void write_directory_atomically(const std::filesystem::path& target, bool overwrite,
                                const std::function<void(const std::filesystem::path&)>& produce);

}  // namespace sgmp
