#pragma once
/// @file pack_file.hpp
/// Reading and writing pack files on disk. This is the only layer of the pack library
/// that touches the file system; algorithms take and return `Pack` values.

#include <filesystem>

#include "sgmp/pack/pack.hpp"

namespace sgmp {

/// Reads a pack file: extended XYZ or LAMMPS/LIGGGHTS `dump custom`, told apart by the
/// first line; gzip-compressed files (by their magic bytes) are read transparently.
/// Throws InputError ("file:line: reason") for malformed or unreadable files.
Pack read_pack_file(const std::filesystem::path& path);

/// Writes `pack` as extended XYZ (gzip-compressed when the name ends in ".gz"), to a
/// temporary file renamed into place. An existing file is kept unless `overwrite`.
/// Throws std::runtime_error naming the path and the reason.
void write_pack_file(const std::filesystem::path& path, const Pack& pack, bool overwrite);

}  // namespace sgmp
