#include "sgmp/report/report_files.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/report/report_plots.hpp"

namespace sgmp::report {
namespace fs = std::filesystem;
namespace {

/// The SVG element of a file, without the XML prolog and doctype, for inlining in HTML.
std::string svg_element(const std::string& svg) {
    const auto start = svg.find("<svg");
    return start == std::string::npos ? svg : svg.substr(start);
}

}  // namespace

ReportContext write_report(const fs::path& directory, bool overwrite, const Report& report,
                           ReportContext context) {
    write_directory_atomically(directory, overwrite, [&](const fs::path& temporary) {
        const PlotResult plots = make_plots(
            context.plots_per_count ? panels_per_count(report) : panels_per_comparison(report),
            context.plots_per_count ? trends_of(report, metrics::ranked_metric_names(
                                                            &metrics::MetricDescriptor::trend_rank))
                                    : std::vector<Trend>{},
            temporary);
        context.plots_made = plots.made;
        context.plots_note = plots.note;
        context.plot_files = plots.files;
        std::vector<std::string> svgs;
        for (const auto& file : plots.files) {
            svgs.push_back(svg_element(read_text_file(temporary / file)));
        }
        write_text_file(temporary / "report.md", render_markdown(report, context));
        write_text_file(temporary / "report.csv", render_csv(report, context));
        write_text_file(temporary / "report.json", render_json(report, context).dump(2) + "\n");
        write_text_file(temporary / "index.html", render_html(report, context, svgs));
        for (const auto& [name, content] : context.extra_files) {
            fs::create_directories((temporary / name).parent_path());  // e.g. pictures/
            write_text_file(temporary / name, content);
        }
    });
    return context;
}

}  // namespace sgmp::report
