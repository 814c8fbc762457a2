#pragma once
/// @file report_render.hpp
/// Text forms of an agreement report: Markdown (for people: a summary first, every number
/// with its unit or marked as a ratio), CSV and JSON (for scripts), and the HTML page that
/// gathers the tables and the plots.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sgmp/report/agreement.hpp"

namespace sgmp::report {

/// What made the report, recorded in every output.
struct ReportContext {
    std::string title = "Agreement report";
    std::string command;  // the command line
    nlohmann::ordered_json parameters;
    /// Markdown placed before the per-comparison summary (headings "## ", bullet lines
    /// "- ", pipe tables and paragraphs; index.html renders the same subset).
    std::string lead_markdown;
    /// Further files written into the report directory: (name, content).
    std::vector<std::pair<std::string, std::string>> extra_files;
    /// Plots: one panel per particle count with every group, instead of one per comparison.
    bool plots_per_count = false;
    bool plots_made = false;
    std::string plots_note;               // why plots were skipped, when they were
    std::vector<std::string> plot_files;  // SVG names, in display order
};

std::string render_markdown(const Report& report, const ReportContext& context);
std::string render_csv(const Report& report, const ReportContext& context);
nlohmann::ordered_json render_json(const Report& report, const ReportContext& context);
/// `svgs` holds the SVG texts of context.plot_files, inlined so the page stands alone.
std::string render_html(const Report& report, const ReportContext& context,
                        const std::vector<std::string>& svgs);

/// HTML of the Markdown subset used by ReportContext::lead_markdown.
std::string markdown_to_html(const std::string& markdown);

/// A JSON number, or null for an infinite or NaN value (an interval without bounds).
nlohmann::ordered_json finite_or_null(double value);

/// The agreement rules in words (used by every output).
std::vector<std::string> rule_statements();

}  // namespace sgmp::report
