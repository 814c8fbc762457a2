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

/// One curve of a plot: a group's mean curves; references are drawn dashed.
struct PlotCurve {
    std::string label;
    const GroupCurves* curves = nullptr;
    bool reference = false;
};

/// One set of four plots (g(r), P(Z), Z(δ), φ(y)) sharing a title and file stem.
struct PlotPanel {
    std::string stem;  // file name stem, e.g. "c0_N1002"
    std::string what;  // title suffix
    std::vector<PlotCurve> curves;
};

/// One panel per comparison: candidate against reference.
std::vector<PlotPanel> panels_per_comparison(const Report& report);
/// One panel per particle count with every group compared at that count (a group drawn
/// once); P(Z) is then drawn at δ = 1e-2 only.
std::vector<PlotPanel> panels_per_count(const Report& report);

/// Writes the data files and gnuplot script into `directory`/plots and runs gnuplot there.
/// The panels point into the report they were made from, which must outlive the call.
PlotResult make_plots(const std::vector<PlotPanel>& panels, const std::filesystem::path& directory);

}  // namespace sgmp::compare
