// Batch summaries (sgmp batch --measure's summary.csv) read as pack summaries
// (precomputed.hpp): one per row, its metrics from the summary's columns.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "precomputed_text.hpp"
#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/metrics/summary_columns.hpp"
#include "sgmp/pack/csv_fields.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/report/agreement.hpp"
#include "sgmp/report/precomputed.hpp"

namespace sgmp::report {

using detail::count_of;
using detail::kUnknown;
using detail::lines_of;
using metrics::coordination_tolerance_names;
using metrics::summary_column_of;
using metrics::SummaryColumn;

namespace {

/// Throws InputError unless every field of line `line` is UTF-8 (paths and parameters reach
/// the JSON outputs).
void check_utf8_fields(const std::vector<std::string>& fields, const std::string& source,
                       std::size_t line) {
    for (const auto& f : fields) {
        if (!is_utf8(f)) {
            throw InputError(source, line,
                             "field '" + f +
                                 "' is not UTF-8 (a Latin-1 byte?): a summary "
                                 "must be UTF-8 text");
        }
    }
}

/// Throws InputError unless `header` (line `line`) is a batch summary's: job first, and the
/// batch summary's marker column.
void check_batch_header(const std::vector<std::string>& header, const std::string& source,
                        std::size_t line) {
    const std::string& marker =
        metrics::metric_with(metrics::MetricRole::BatchSummary).summary_column;
    if (std::find(header.begin(), header.end(), marker) == header.end() ||
        header.front() != "job") {
        throw InputError(source, line,
                         "is not an sgmp batch summary (no job, " + marker + " columns)");
    }
}

/// One row of a batch summary, its fields read by column name.
class BatchRow {
  public:
    BatchRow(const std::vector<std::string>& header, const std::vector<std::string>& fields,
             const std::string& source, std::size_t line)
        : header_(header), fields_(fields), source_(source), line_(line) {}

    /// The field of column `name`; throws InputError (at line 1) when there is no such column.
    const std::string& field(const std::string& name) const {
        const auto at = std::find(header_.begin(), header_.end(), name);
        if (at == header_.end()) {
            throw InputError(source_, 1, "has no column '" + name + "'");
        }
        return fields_[static_cast<std::size_t>(at - header_.begin())];
    }

    /// Whether the header has a column `name`.
    bool has(const std::string& name) const {
        return std::find(header_.begin(), header_.end(), name) != header_.end();
    }

    /// The number in column `name`; throws InputError when the field is not one.
    double number(const std::string& name) const {
        const std::string& f = field(name);
        double value = 0.0;
        const auto r = std::from_chars(f.data(), f.data() + f.size(), value);
        if (f.empty() || r.ec != std::errc() || r.ptr != f.data() + f.size()) {
            throw InputError(
                source_, line_,
                "'" + name + "' is '" + f + "', not a number (was the batch run with --measure?)");
        }
        return value;
    }

    /// A measured value in column `name`: a metric not measured is an empty field (read as
    /// NaN, not judged); a field that holds "nan" or "inf" claims a measured value that
    /// cannot be one, and is refused.
    double measured(const std::string& name) const {
        const double value = number(name);
        if (!std::isfinite(value)) {
            throw InputError(source_, line_,
                             "'" + name + "' is '" + field(name) +
                                 "': a measured value must be finite (a metric not "
                                 "measured is an empty field)");
        }
        return value;
    }

    const std::vector<std::string>& header() const { return header_; }
    const std::vector<std::string>& fields() const { return fields_; }
    const std::string& source() const { return source_; }
    std::size_t line() const { return line_; }

  private:
    const std::vector<std::string>& header_;
    const std::vector<std::string>& fields_;
    const std::string& source_;
    std::size_t line_;
};

/// The summary of the pack one batch row names: its parameters and seed as provenance, its
/// count, and the scalar and Z metrics its columns hold (an optional column absent or empty:
/// unknown).
PackSummary summary_of_batch_row(const BatchRow& row) {
    const auto& header = row.header();
    PackSummary s;
    s.source = row.field("path");
    if (s.source.empty()) {
        throw InputError(row.source(), row.line(), "names no pack (a batch run with --no-packs)");
    }
    for (std::size_t c = 1; c < header.size(); ++c) {
        if (header[c] == "seconds") {
            break;  // the parameters and the seed come first
        }
        s.provenance.emplace_back(header[c], row.fields()[c]);
    }
    s.count = count_of(row.number("count"), row.source(), row.line());
    s.diameter = kUnknown;
    for (const auto& rule : metric_rules()) {
        if (rule.kind != MetricKind::Scalar) {
            continue;
        }
        double v = kUnknown;
        const SummaryColumn* column = summary_column_of(rule.name);
        const bool absent = column != nullptr && column->optional &&
                            (!row.has(column->column) || row.field(column->column).empty());
        if (column != nullptr && !absent) {
            v = row.measured(column->column);
        }
        s.scalars.push_back(v);
    }
    const auto& names = coordination_tolerance_names();
    for (std::size_t t = 0; t < names.size(); ++t) {
        s.z_mean.push_back(
            row.measured(summary_column_of(metrics::coordination_metric(t).name)->column));
    }
    s.p_z.assign(names.size(), {});
    return s;
}

}  // namespace

std::vector<std::pair<std::string, PackSummary>> summaries_from_batch(std::string_view text,
                                                                      const std::string& source) {
    const auto lines = lines_of(text);
    std::vector<std::string> header;
    std::vector<std::pair<std::string, PackSummary>> out;
    for (std::size_t n = 0; n < lines.size(); ++n) {
        if (lines[n].empty() || lines[n].front() == '#') {
            continue;
        }
        const auto fields = split_csv_line(lines[n]);
        check_utf8_fields(fields, source, n + 1);
        if (header.empty()) {
            header = fields;
            check_batch_header(header, source, n + 1);
            continue;
        }
        if (fields.size() != header.size()) {
            throw InputError(source, n + 1, "has another number of fields than the header");
        }
        PackSummary s = summary_of_batch_row(BatchRow(header, fields, source, n + 1));
        out.emplace_back(s.source, std::move(s));
    }
    if (header.empty()) {
        throw InputError(source, 0, "holds no header row");
    }
    return out;
}

}  // namespace sgmp::report
