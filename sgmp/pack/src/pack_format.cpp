#include "sgmp/pack/pack_format.hpp"

#include <array>

namespace sgmp {
namespace {

struct FormatName {
    PackFormat format;
    std::string_view name;
    std::string_view extension;
};

// The one name table. Longer endings come before their suffixes (".xyz.gz" before ".xyz").
constexpr std::array<FormatName, 6> kFormats{{
    {PackFormat::xyz, "xyz", ".xyz"},
    {PackFormat::xyz_gz, "xyz.gz", ".xyz.gz"},
    {PackFormat::lammps_data, "data", ".data"},
    {PackFormat::lammps_dump, "dump", ".dump"},
    {PackFormat::vtk, "vtk", ".vtk"},
    {PackFormat::vtp, "vtp", ".vtp"},
}};

constexpr std::array<PackFormat, 6> kOrder{PackFormat::xyz,         PackFormat::xyz_gz,
                                           PackFormat::lammps_data, PackFormat::lammps_dump,
                                           PackFormat::vtk,         PackFormat::vtp};

const FormatName& entry(PackFormat format) {
    for (const auto& row : kFormats) {
        if (row.format == format) {
            return row;
        }
    }
    return kFormats.front();
}

}  // namespace

bool has_container_file(PackFormat format) {
    return format == PackFormat::vtk || format == PackFormat::vtp;
}

std::span<const PackFormat> all_pack_formats() {
    return kOrder;
}

std::string_view to_string(PackFormat format) {
    return entry(format).name;
}

std::optional<PackFormat> parse_pack_format(std::string_view name) {
    for (const auto& row : kFormats) {
        if (row.name == name) {
            return row.format;
        }
    }
    return std::nullopt;
}

std::string pack_format_choices() {
    std::string text = "one of ";
    for (std::size_t i = 0; i < kFormats.size(); ++i) {
        text += (i > 0 ? ", " : "");
        text += kFormats[i].name;
    }
    return text;
}

std::string_view extension_of(PackFormat format) {
    return entry(format).extension;
}

std::optional<PackFormat> format_from_extension(const std::filesystem::path& path) {
    const std::string name = path.filename().string();
    std::optional<PackFormat> best;
    std::size_t best_length = 0;
    for (const auto& row : kFormats) {
        const auto& ending = row.extension;
        if (name.size() > ending.size() && name.ends_with(ending) && ending.size() > best_length) {
            best = row.format;
            best_length = ending.size();
        }
    }
    return best;
}

}  // namespace sgmp
