#include "sgmp/batch/summary.hpp"
#include "sgmp/pack/csv_fields.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/version.hpp"

namespace sgmp::batch {
namespace {

std::string optional_number(const std::optional<double>& value) {
    return value ? format_number(*value) : std::string();
}

}  // namespace

SummarySchema::SummarySchema(std::vector<std::string> metric_columns)
    : metric_columns_(std::move(metric_columns)) {}

std::vector<std::string> SummarySchema::header() const {
    std::vector<std::string> header{"job"};
    for (const Parameter& p : parameters()) {
        header.push_back(p.name);
    }
    header.insert(header.end(), {"seed", "seconds", "measure_seconds"});
    header.insert(header.end(), metric_columns_.begin(), metric_columns_.end());
    header.emplace_back("path");
    return header;
}

std::string SummarySchema::line(const SummaryRow& row) const {
    std::vector<std::string> fields{std::to_string(row.job)};
    fields.insert(fields.end(), row.values.begin(), row.values.end());
    fields.push_back(std::to_string(row.seed));
    fields.push_back(optional_number(row.seconds));
    fields.push_back(optional_number(row.measure_seconds));
    if (row.metric_fields.empty()) {
        fields.insert(fields.end(), metric_columns_.size(), "");
    } else if (row.metric_fields.size() == metric_columns_.size()) {
        fields.insert(fields.end(), row.metric_fields.begin(), row.metric_fields.end());
    } else {
        throw std::invalid_argument("summary row of job " + std::to_string(row.job) + ": " +
                                    std::to_string(row.metric_fields.size()) +
                                    " metric fields for " + std::to_string(metric_columns_.size()) +
                                    " columns");
    }
    fields.push_back(row.path);
    std::string line;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        line += (i == 0 ? "" : ",") + csv_field(fields[i]);
    }
    return line + "\n";
}

std::string SummarySchema::text(const std::vector<std::string>& lines) const {
    std::string text;
    const auto header = this->header();
    for (std::size_t i = 0; i < header.size(); ++i) {
        text += (i == 0 ? "" : ",") + header[i];
    }
    text += "\n# tool: sgmp " + std::string(version()) + "\n";
    text +=
        "# rule: one row per pack in job order; seconds and measure_seconds are timings, "
        "every other column depends on the inputs only\n";
    for (const std::string& line : lines) {
        text += line;
    }
    return text;
}

SummaryTable SummarySchema::parse(std::string_view text, const std::string& source) const {
    SummaryTable table;
    const auto expected = header();
    std::size_t number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++number;
        if (line.empty() || line.front() == '#') {
            continue;
        }
        const auto fields = split_quoted_csv_line(line);
        if (!fields) {
            throw InputError(source, number, "a quoted field is not closed");
        }
        if (table.header.empty()) {
            if (*fields != expected) {
                throw InputError(source, number,
                                 "the header is not that of an sgmp batch summary of this "
                                 "version");
            }
            table.header = *fields;
            continue;
        }
        if (fields->size() != expected.size()) {
            throw InputError(source, number,
                             "has " + std::to_string(fields->size()) + " fields, the header " +
                                 std::to_string(expected.size()));
        }
        SummaryTable::Row row;
        const std::string& job = fields->front();
        const auto parsed = std::from_chars(job.data(), job.data() + job.size(), row.job);
        if (job.empty() || parsed.ec != std::errc() || parsed.ptr != job.data() + job.size()) {
            throw InputError(source, number, "job '" + job + "' is not a whole number");
        }
        row.fields = *fields;
        row.line = std::string(line);
        table.rows.push_back(std::move(row));
    }
    if (table.header.empty()) {
        throw InputError(source, 0, "holds no header row");
    }
    return table;
}

std::string SummarySchema::merge(const std::vector<SummaryTable>& tables) const {
    std::vector<const SummaryTable::Row*> rows;
    for (const SummaryTable& table : tables) {
        for (const SummaryTable::Row& row : table.rows) {
            rows.push_back(&row);
        }
    }
    std::stable_sort(rows.begin(), rows.end(),
                     [](const auto* a, const auto* b) { return a->job < b->job; });
    std::vector<std::string> lines;
    lines.reserve(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (i > 0 && rows[i]->job == rows[i - 1]->job) {
            throw std::invalid_argument("job " + std::to_string(rows[i]->job) +
                                        " appears in more than one summary row");
        }
        lines.push_back(rows[i]->line + "\n");
    }
    return text(lines);
}

}  // namespace sgmp::batch
