#pragma once
/// @file atomic_file.hpp
/// All-or-nothing outputs: content goes to a temporary beside the target and is renamed
/// into place only when complete, so a crash or error never leaves a half-written file.
/// A temporary is named `.NAME.tmp-PID.HOST` (the writer's process and host), so a later
/// run can tell the leftovers of a killed writer from a live one's work.

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sgmp/pack/interrupt.hpp"

namespace sgmp {

/// The target of a write exists and may not be replaced (no overwrite): "<path>: exists;
/// pass --force to replace it". A std::runtime_error like every other refusal here.
class FileExists : public std::runtime_error {
  public:
    explicit FileExists(const std::filesystem::path& path);
    /// The file that exists (a front end words the refusal in its own terms).
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

/// Fails unless `target` can be written: its parent directory exists (or can be created)
/// and, without `overwrite`, the target does not exist. Throws std::runtime_error
/// "<path>: <reason>" so callers can refuse before any expensive work.
void check_writable(const std::filesystem::path& target, bool overwrite);

/// Writes a file atomically: `produce` writes to a stream on a temporary file in the
/// same directory, which is flushed and renamed to `target`. The temporary is removed if
/// `produce` throws. Content is gzip-compressed when `target` ends in ".gz". Without
/// `overwrite`, a target that appeared while `produce` ran is kept and FileExists thrown.
void write_file_atomically(const std::filesystem::path& target, bool overwrite,
                           const std::function<void(std::ostream&)>& produce);

/// One file of a set written as a whole (write_files_atomically).
struct AtomicOutput {
    std::filesystem::path target;
    std::function<void(std::ostream&)> produce;
};

/// Writes several files as one, e.g. a legacy VTK pack and its container: each is
/// produced into its own temporary (as write_file_atomically), and only when all are
/// complete are they renamed into place, in order, with SIGINT and SIGTERM held off
/// (run_uninterrupted), so an interrupt leaves either the old set or the new one. When a
/// rename fails, the targets already replaced get their old content back.
void write_files_atomically(const std::vector<AtomicOutput>& outputs, bool overwrite);

/// Removes the temporaries (files or directories `.NAME.tmp-PID.HOST`) in `directory`
/// that writers on this host left behind: their process no longer runs (a SIGKILL, a
/// power cut). Temporaries of running processes and of other hosts are kept. Returns how
/// many were removed; errors are ignored (a leftover costs only space).
std::size_t remove_stale_temporaries(const std::filesystem::path& directory);

/// Writes what `produce` writes to `path`, replacing it: for files inside a directory that
/// is itself being built atomically (write_directory_atomically) or a scratch directory.
/// Throws std::runtime_error "<path>: write failed: <reason>" (or "cannot write: <reason>").
void write_stream_file(const std::filesystem::path& path,
                       const std::function<void(std::ostream&)>& produce);

/// write_stream_file of `text`.
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
/// with `overwrite`, and only after `produce` succeeded). The directory records what it
/// was written with in `.sgmp-output` (kOutputRecord), and `overwrite` replaces an
/// existing target only when every entry it holds is in that record or among the new
/// outputs: a directory holding anything else (the current directory, a folder of packs)
/// is refused with "<target>: holds <entry>, which this command did not write …", as are
/// a target that is a symbolic link, not a directory, or the current directory or one of
/// its ancestors. Nothing is deleted that the command did not write.
inline constexpr const char* kOutputRecord = ".sgmp-output";

void write_directory_atomically(const std::filesystem::path& target, bool overwrite,
                                const std::function<void(const std::filesystem::path&)>& produce);

}  // namespace sgmp
