#pragma once
/// @file summary.hpp
/// `summary.csv`, the one table of a sweep: one row per pack, in job order (plan.hpp), with
/// the job number, every parameter, the seed, the seconds spent packing and measuring, the
/// metrics (columns and values given by the front end) and the pack's path. The layout is the
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

struct SummaryRow {
    std::size_t job = 0;
    ParameterValues values;
    std::uint64_t seed = 0;
    std::optional<double> seconds;           // packing; absent for a pack made earlier
    std::optional<double> measure_seconds;   // absent when not measured
    std::vector<std::string> metric_fields;  // one per metric column; empty when not measured
    std::string path;                        // empty with --no-packs
};

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

/// The columns of one summary: `job`, every parameter, `seed`, `seconds`,
/// `measure_seconds`, the metric columns the front end names (the batch library measures
/// nothing itself; sgmp/app gives it sgmp-compare's, compare/metrics summary_columns.hpp),
/// and `path`.
class SummarySchema {
  public:
    explicit SummarySchema(std::vector<std::string> metric_columns);

    /// Names of the columns.
    std::vector<std::string> header() const;

    /// One row as a CSV line, ending in '\n'. Throws std::invalid_argument for a measured
    /// row whose metric fields are not one per metric column.
    std::string line(const SummaryRow& row) const;

    /// The whole table: header, `#` provenance lines (`tool`), then `lines` (line() texts)
    /// in the order given.
    std::string text(const std::vector<std::string>& lines) const;

    /// Parses a summary's text. Throws InputError ("source:line: reason") for a header that
    /// is not header(), a row with another field count or job number that is not a whole
    /// number.
    SummaryTable parse(std::string_view text, const std::string& source) const;

    /// The tables' rows as one summary text in job order (shard summaries merged: the
    /// serial run's table). Throws std::invalid_argument naming the job when one appears
    /// twice.
    std::string merge(const std::vector<SummaryTable>& tables) const;

  private:
    std::vector<std::string> metric_columns_;
};

}  // namespace sgmp::batch
