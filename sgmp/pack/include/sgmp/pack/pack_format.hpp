#pragma once
/// @file pack_format.hpp
/// The pack file formats the library writes, with one name table: the name given to
/// `--to`, the file name endings that select it, and what each carries.
///
/// | name   | endings            | file                                                   |
/// | ------ | ------------------ | ------------------------------------------------------ |
/// | xyz    | .xyz               | extended XYZ (OVITO, ASE), the testbed's own format    |
/// | xyz.gz | .xyz.gz            | the same, gzip-compressed                              |
/// | data   | .data              | LAMMPS / LIGGGHTS data file, `atom_style sphere`       |
/// | dump   | .dump              | LAMMPS `dump custom` (id type x y z radius bin)        |
/// | vtk    | .vtk               | legacy VTK PolyData (ParaView), plus a container file  |
/// | vtp    | .vtp               | VTK XML PolyData, binary arrays, plus a container file |

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace sgmp {

enum class PackFormat { xyz, xyz_gz, lammps_data, lammps_dump, vtk, vtp };

/// Whether the format writes the container as a second file (vtk, vtp).
bool has_container_file(PackFormat format);

/// Every format, in the order of the name table.
std::span<const PackFormat> all_pack_formats();

/// The format's name as `--to` takes it ("xyz", "xyz.gz", "data", "dump", "vtk", "vtp").
std::string_view to_string(PackFormat format);

/// The format named `name`; nullopt for an unknown name.
std::optional<PackFormat> parse_pack_format(std::string_view name);

/// "one of xyz, xyz.gz, data, dump, vtk, vtp" — the rule quoted in error messages.
std::string pack_format_choices();

/// The file name ending (with its dot) of each format: ".xyz", ".xyz.gz", ".data", ...
std::string_view extension_of(PackFormat format);

/// The format selected by the end of `path`'s file name; nullopt when none matches.
std::optional<PackFormat> format_from_extension(const std::filesystem::path& path);

}  // namespace sgmp
