#pragma once
/// @file report_plots.hpp
/// Plots of a report drawn by gnuplot as SVG: the trends of φ, Z and the split ratio
/// against N, and per comparison (or per count) g(r) beyond contact with a contact-region
/// inset, P(Z), Z(δ) and φ(y) (mean curves over each side's packs; references as bands
/// of mean ± 2 sd where shown). Okabe–Ito colours, legends outside the data.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sgmp/report/agreement.hpp"

namespace sgmp::report {

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
    std::string group;  // the group's label, which picks its colour
    /// Its place among `PlotPanel::series` when the panel is a part of a split one.
    std::size_t slot = 0;
};

/// One set of four plots (g(r), P(Z), Z(δ), φ(y)) sharing a title and file stem.
struct PlotPanel {
    std::string stem;  // file name stem, e.g. "c0_N1002"
    std::string what;  // title suffix
    std::vector<PlotCurve> curves;
    /// For a part of a split panel: the whole panel's series (label, reference), so that a
    /// group keeps its colour in every part; empty otherwise.
    std::vector<std::pair<std::string, bool>> series{};
};

/// One panel per comparison: candidate against reference.
std::vector<PlotPanel> panels_per_comparison(const Report& report);
/// Per particle count, the groups compared at that count (a group drawn once) in panels
/// of at most kMaxSeries curves (split_series); P(Z) is then drawn at δ = 1e-2 only.
/// The first panel of count N has the stem "N<N>", the others "N<N>_2", "N<N>_3", …
std::vector<PlotPanel> panels_per_count(const Report& report);

/// Most series a plot shows.
inline constexpr std::size_t kMaxSeries = 6;

/// Series of one plot split into plots of at most kMaxSeries: when both kinds are present,
/// every chunk of at most 3 references (the classes) is drawn with every chunk of at most
/// kMaxSeries − min(references, 3) candidates; otherwise chunks of kMaxSeries. Each chunk
/// lists indices into `reference` (candidates first), in their order.
std::vector<std::vector<std::size_t>> split_series(const std::vector<bool>& reference);

/// One group's values of a scalar metric against N: a candidate (points and lines) or a
/// reference (a mean ± 2 sd band).
struct Trend {
    std::string metric;
    std::string metric_label;
    std::string label;
    bool reference = false;
    std::vector<double> count;
    std::vector<double> mean;
    std::vector<double> sd;
};
/// The trends of `metrics` over every comparison of the report.
std::vector<Trend> trends_of(const Report& report, const std::vector<std::string>& metrics);

/// Writes the data files and gnuplot script into `directory`/plots and runs gnuplot there:
/// one plot per trend metric (trend_<metric>.svg), then the panels. The panels point into
/// the report they were made from, which must outlive the call.
PlotResult make_plots(const std::vector<PlotPanel>& panels, const std::vector<Trend>& trends,
                      const std::filesystem::path& directory);

}  // namespace sgmp::report
