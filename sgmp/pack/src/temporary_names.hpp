#pragma once
/// @file temporary_names.hpp
/// What the atomic writers (atomic_file.cpp, atomic_directory.cpp) share: the name of a
/// temporary beside its target, `.NAME.KIND-PID.HOST`, and its creation, which never
/// follows a symbolic link.

#include <filesystem>

namespace sgmp {

/// `.NAME.KIND-PID.HOST` in the directory of `target` (this process, this host).
std::filesystem::path sibling_temporary(const std::filesystem::path& target, const char* kind);

/// The directory of `target` ("." for a bare file name).
std::filesystem::path parent_of(const std::filesystem::path& target);

/// Flushes a directory's entries to disk, so a rename into it survives a power cut.
void sync_directory(const std::filesystem::path& directory);

/// Creates `path` as a new, empty file for writing (O_CREAT | O_EXCL | O_NOFOLLOW): what
/// already sits at that name (a leftover, a planted symbolic link) is removed first, never
/// written through. Returns the descriptor, or -1 with errno set.
int create_exclusive(const std::filesystem::path& path);

}  // namespace sgmp
