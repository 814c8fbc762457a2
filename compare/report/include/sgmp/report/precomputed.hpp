#pragma once
/// @file precomputed.hpp
/// Metrics measured earlier, so that `crossval` and `report` need not read and measure the
/// packs again (a sweep measured on many nodes is compared in one step):
/// - the outputs of `sgmp-compare measure` for one pack (`NAME.metrics.json` with its
///   `NAME.g_r.csv` and `NAME.phi_y.csv`): every metric, exactly as measuring the pack
///   gives it (numbers are written so that they read back exactly);
/// - the rows of an `sgmp batch --measure` summary (`summary.csv`): the scalar metrics
///   it holds (φ, Z(δ) at every tolerance, overlaps, the deepest overlap, wall overlaps, the
///   split ratio, the Voronoi mean when measured). It holds no curves and no Q6, so those
///   metrics are `inconclusive` (not measured) for such packs.
/// A metric a pack lacks is NaN (scalars) or an empty curve (PackSummary::has_curves).

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sgmp/report/agreement.hpp"

namespace sgmp::report {

/// True for a path naming a `measure` metrics file (ends in ".metrics.json").
bool is_metrics_json(std::string_view path);

/// The sibling curve file of a metrics file: `a/b.metrics.json` → `a/b.<kind>.csv`.
std::string sibling_csv(const std::string& metrics_path, const std::string& kind);

/// The summary of one pack from its `measure` outputs. `source` names the metrics file in
/// errors; the summary's source is the pack path `measure` recorded. `parameters` are the
/// measurement parameters of the run reading them (measure_parameters): a file measured
/// with others is refused. Throws sgmp::InputError naming the file and the reason.
PackSummary summary_from_measure(const std::string& source, const nlohmann::ordered_json& metrics,
                                 std::string_view g_r_csv, std::string_view phi_y_csv,
                                 const nlohmann::ordered_json& parameters);

/// The rows of a batch summary as (pack path, summary) pairs, in row order; rows without a
/// path (made with --no-packs) or without metrics (made without --measure) are refused.
/// Throws sgmp::InputError ("source:line: reason").
std::vector<std::pair<std::string, PackSummary>> summaries_from_batch(std::string_view text,
                                                                      const std::string& source);

}  // namespace sgmp::report
