#pragma once
/// @file report_plots.hpp
/// Plots of a report drawn by gnuplot as SVG: per comparison, g(r) of both sides overlaid,
/// P(Z), Z(δ) and φ(y) (mean curves over each side's packs).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sgmp/compare/agreement.hpp"

namespace sgmp::compare {

/// The gnuplot executable: $SGMP_GNUPLOT when set (empty = none), else `gnuplot` on PATH.
std::optional<std::filesystem::path> find_gnuplot();

struct PlotResult {
    bool made = false;
    std::string note;                // why not, when not made
    std::vector<std::string> files;  // SVG paths relative to the report directory
};

/// Writes the data files and gnuplot script into `directory`/plots and runs gnuplot there.
PlotResult make_plots(const Report& report, const std::filesystem::path& directory);

}  // namespace sgmp::compare
