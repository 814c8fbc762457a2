#pragma once
/// @file summary.hpp
/// `summary.csv`, the one table of a sweep: one row per pack, in job order (plan.hpp), with
/// the job number, every parameter, the seed, the seconds spent packing and measuring, the
/// metrics (φ of the control volume, mean Z at every gap tolerance δ, overlaps, the split
/// ratio, optionally the Voronoi mean local φ) and the pack's path. The layout is the
/// testbed's CSV layout (header row, `#` lines, rows; RFC 4180 quoting). Numbers are the
/// shortest text that reads back exactly, so the same packs give the same bytes; only
/// `seconds` and `measure_seconds` are timings.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sgmp/batch/parameters.hpp"

namespace sgmp::batch {

/// Metrics of one pack (definitions in compare/README.md).
struct PackMetrics {
    double phi = 0.0;
    std::vector<double> z_mean;         // per gap tolerance, compare::coordination_tolerances()
    std::int64_t overlaps = 0;          // particle pairs deeper than 1e-9 d
    double overlap_max = 0.0;           // deepest pair overlap, over d
    std::int64_t wall_overlaps = 0;     // particles crossing a wall or the floor by > 1e-9 d
    double split_ratio = 0.0;           // g(√3 d) / g(2 d)
    std::optional<double> voronoi_phi;  // mean Voronoi local φ, when measured
};

struct SummaryRow {
    std::size_t job = 0;
    ParameterValues values;
    std::uint64_t seed = 0;
    std::optional<double> seconds;          // packing; absent for a pack made earlier
    std::optional<double> measure_seconds;  // absent when not measured
    std::optional<PackMetrics> metrics;
    std::string path;  // empty with --no-packs
};

/// Names of the columns. The timing columns are `seconds` and `measure_seconds`.
std::vector<std::string> summary_header();

/// One row as a CSV line, ending in '\n'.
std::string summary_line(const SummaryRow& row);

/// The whole table: header, `#` provenance lines (`tool`), then `lines` (summary_line
/// texts) in the order given.
std::string summary_text(const std::vector<std::string>& lines);

/// A summary read back: its header fields and rows (fields and job number).
struct SummaryTable {
    std::vector<std::string> header;
    struct Row {
        std::size_t job = 0;
        std::vector<std::string> fields;
        std::string line;  // as written, without '\n'
    };
    std::vector<Row> rows;
};

/// Parses a summary's text. Throws InputError ("source:line: reason") for a header that is
/// not summary_header(), a row with another field count or job number that is not a whole
/// number.
SummaryTable parse_summary(std::string_view text, const std::string& source);

/// The tables' rows as one summary text in job order (shard summaries merged: the serial
/// run's table). Throws std::invalid_argument naming the job when one appears twice.
std::string merge_summaries(const std::vector<SummaryTable>& tables);

}  // namespace sgmp::batch
