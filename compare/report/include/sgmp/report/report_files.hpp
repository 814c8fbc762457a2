#pragma once
/// @file report_files.hpp
/// Writes a report directory atomically: report.md, report.csv, report.json, plots/ and a
/// self-contained index.html. The directory appears complete or not at all.

#include <filesystem>

#include "sgmp/report/report_render.hpp"

namespace sgmp::report {

/// Existing `directory` is replaced only with `overwrite`. Returns the context as used
/// (with the plot outcome filled in).
ReportContext write_report(const std::filesystem::path& directory, bool overwrite,
                           const Report& report, ReportContext context);

}  // namespace sgmp::report
