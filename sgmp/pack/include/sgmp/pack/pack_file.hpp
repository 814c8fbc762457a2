#pragma once
/// @file pack_file.hpp
/// Reading and writing pack files on disk. This is the only layer of the pack library
/// that touches the file system; algorithms take and return `Pack` values, and the format
/// writers (xyz_format, lammps_data_format, dump_format, vtk_format) produce text only.

#include <filesystem>

#include "sgmp/pack/pack.hpp"
#include "sgmp/pack/pack_format.hpp"
#include "sgmp/pack/read_options.hpp"

namespace sgmp {

/// Reads a pack file: extended XYZ, LAMMPS/LIGGGHTS `dump custom` (first line "ITEM:") or
/// a LAMMPS data file (first line "LAMMPS data file", or the name ends in ".data");
/// gzip-compressed files (by their magic bytes) are read transparently. Extended XYZ
/// gives its last frame. Throws InputError ("file:line: reason") for malformed or
/// unreadable files.
Pack read_pack_file(const std::filesystem::path& path);

/// The same, with a frame and a radius chosen (read_options.hpp). `options.frame` applies
/// to extended XYZ only (a dump gives its last complete snapshot; asking another frame of
/// a dump or data file is an InputError); `options.radius` replaces every radius (an
/// extended XYZ file may then lack a radius column; dump and data files carry one).
PackRead read_pack_file(const std::filesystem::path& path, const ReadOptions& options);

/// Writes `pack` as extended XYZ (gzip-compressed when the name ends in ".gz"), to a
/// temporary file renamed into place. An existing file is kept unless `overwrite`.
/// Throws std::runtime_error naming the path and the reason.
void write_pack_file(const std::filesystem::path& path, const Pack& pack, bool overwrite);

struct WriteOptions {
    /// Replace existing outputs (`--force`); without it an existing output is an error.
    bool overwrite = false;
};

/// The second file of the vtk and vtp formats: "pack.vtk" → "pack.container.vtk",
/// "pack.vtp" → "pack.container.vtp".
std::filesystem::path container_file_for(const std::filesystem::path& path);

/// Writes `pack` in `format` (pack_format.hpp), all or nothing: every file of the format
/// goes to a temporary renamed into place (vtk writes two files: `path` and
/// `container_file_for(path)`). Throws std::invalid_argument when `format` cannot carry the
/// pack or does not match the name ("xyz.gz" needs a name ending in ".gz", and only it
/// may), std::runtime_error for a refused or failed write; no output is left either way.
void write_pack_as(const std::filesystem::path& path, const Pack& pack, PackFormat format,
                   const WriteOptions& options);

}  // namespace sgmp
