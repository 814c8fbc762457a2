#pragma once
/// @file bounded_file.hpp
/// Reading a whole file into memory with a stated bound. The size is checked before any
/// byte is read (fstat of what the path names, through symbolic links: a sparse file of
/// 8 GB is refused at once), and the read itself stops one byte past the cap, so a device
/// or pipe with no size (/dev/zero, a link to it, a FIFO) costs at most cap + 1 bytes.
/// Refusals are one InputError naming the file and the cap: "FILE: N bytes, more than the
/// cap of CAP bytes on WHAT" (or "FILE: more than CAP bytes, the cap on WHAT" for a stream).
#include <cstdint>
#include <filesystem>
#include <string>

namespace sgmp {

/// Caps of the whole-file readers (bytes). Each is far above the real files (a summary of
/// 10⁵ packs is ~60 MB; a metrics.json a few kB; a config or size distribution a few
/// hundred bytes) and far below what a process may allocate.
inline constexpr std::uint64_t kMaxSummaryBytes = std::uint64_t{256} << 20;
inline constexpr std::uint64_t kMaxMetricsBytes = std::uint64_t{64} << 20;
inline constexpr std::uint64_t kMaxSmallFileBytes = std::uint64_t{16} << 20;

/// The cap actually applied: `cap`, or the environment's SGMP_MAX_FILE_BYTES when that is
/// a smaller positive integer (the tests use it to show a refusal with small files).
std::uint64_t effective_cap(std::uint64_t cap);

/// The whole content of `path`, at most effective_cap(cap) bytes; `what` names the file's
/// role in the refusal (e.g. "a batch summary"). Throws InputError when it cannot be opened
/// or read, or is larger than the cap.
std::string read_bounded_file(const std::filesystem::path& path, std::uint64_t cap,
                              const std::string& what);

}  // namespace sgmp
