#pragma once
/// @file summary_columns.hpp
/// The metric columns of `sgmp batch`'s summary.csv, drawn from the metric table
/// (metric_descriptors.hpp): the one list its writer (the measure hook sgmp/app gives the
/// batch) and its reader (report/batch_summaries.cpp) share. Each column holds one scalar of a
/// Measurement (measure.hpp), named as in summary.csv and as in `measure`'s metrics.json.
///
/// The summary measures g(r) out to kSummaryGrRange only: the split ratio's windows end at
/// 2.05 d, and the pair search grows as the range cubed (5 d, measure's default, costs
/// eight times as much at N = 10⁴). The split ratio's density ρ cancels in the ratio, so
/// it equals `measure`'s up to rounding (10⁻¹⁵ relative, checked on a 10⁴ pack).

#include <optional>
#include <string>
#include <vector>

#include "sgmp/metrics/measure.hpp"
#include "sgmp/pack/pack.hpp"

namespace sgmp::metrics {

inline constexpr double kSummaryGrRange = 2.1;

struct SummaryColumn {
    std::string column;  ///< the summary.csv header field
    std::string metric;  ///< the metrics.json (and metric_rules()) name of the same value
    bool integer;        ///< written as a whole number
    bool optional;       ///< may be empty or absent in a measured row (Voronoi not asked for)
    /// The value; nullopt when the measurement holds none (Voronoi not asked for).
    std::optional<double> (*value)(const Measurement& m, std::size_t tolerance);
    std::size_t tolerance = 0;  ///< index into coordination_tolerances() for Z columns
};

/// The metrics of metric_descriptors.hpp with a summary column, in summary_rank order.
const std::vector<SummaryColumn>& summary_columns();

/// The header fields of summary_columns().
std::vector<std::string> summary_column_names();

/// The summary.csv column of a metrics.json metric name; nullptr when the summary has none.
const SummaryColumn* summary_column_of(const std::string& metric);

/// Measures `pack` as the summary does (measure's defaults, g(r) to kSummaryGrRange,
/// Voronoi when asked) and formats every column: the shortest text that reads back exactly,
/// whole numbers for counts, "" for a value not measured.
std::vector<std::string> summary_fields(const Pack& pack, bool voronoi, unsigned threads);

}  // namespace sgmp::metrics
