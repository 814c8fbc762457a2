#pragma once
/// @file crossval_render.hpp
/// Views of the cross-validation model (crossval.hpp): the terminal headline, the Markdown
/// lead of the report (which mode stands in for which class, the verdict matrix, the
/// headline table, the thesis beside us), headline.csv and crossval.json.
///
/// Verdict marks, one per count in ascending N: ✓ agree, ✗ differ, ◌ inconclusive,
/// · not compared.

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "sgmp/report/crossval.hpp"

namespace sgmp::report {

/// The mark of a verdict (see the file comment).
std::string_view verdict_mark(Verdict verdict);

/// Plain-text headline table for the terminal.
std::string render_headline_text(const CrossValidation& cv);
/// Markdown sections placed first in the report.
std::string render_crossval_markdown(const CrossValidation& cv);
/// The headline as a tidy CSV: one row per (count, candidate, reference, headline metric),
/// header row first (csv_text.hpp); `command` goes into its `#` lines.
std::string render_headline_csv(const CrossValidation& cv, const std::string& command);
nlohmann::ordered_json crossval_json(const CrossValidation& cv);

}  // namespace sgmp::report
