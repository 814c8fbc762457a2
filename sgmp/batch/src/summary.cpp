#include "sgmp/batch/summary.hpp"
#include "sgmp/pack/csv_fields.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

#include "sgmp/compare/csv_text.hpp"
#include "sgmp/compare/measure.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/version.hpp"

namespace sgmp::batch {
namespace {

std::string optional_number(const std::optional<double>& value) {
    return value ? format_number(*value) : std::string();
}

}  // namespace

std::vector<std::string> summary_header() {
    std::vector<std::string> header{"job"};
    for (const Parameter& p : parameters()) {
        header.push_back(p.name);
    }
    header.insert(header.end(), {"seed", "seconds", "measure_seconds", "phi"});
    for (const std::string& name : compare::coordination_tolerance_names()) {
        header.push_back("z_" + name);
    }
    header.insert(header.end(), {"overlaps", "overlap_max", "wall_overlaps", "split_ratio",
                                 "voronoi_phi_mean", "path"});
    return header;
}

std::string summary_line(const SummaryRow& row) {
    std::vector<std::string> fields{std::to_string(row.job)};
    fields.insert(fields.end(), row.values.begin(), row.values.end());
    fields.push_back(std::to_string(row.seed));
    fields.push_back(optional_number(row.seconds));
    fields.push_back(optional_number(row.measure_seconds));
    const std::size_t tolerances = compare::coordination_tolerances().size();
    if (row.metrics) {
        const PackMetrics& m = *row.metrics;
        fields.push_back(format_number(m.phi));
        for (std::size_t i = 0; i < tolerances; ++i) {
            fields.push_back(i < m.z_mean.size() ? format_number(m.z_mean[i]) : "");
        }
        fields.push_back(std::to_string(m.overlaps));
        fields.push_back(format_number(m.overlap_max));
        fields.push_back(std::to_string(m.wall_overlaps));
        fields.push_back(format_number(m.split_ratio));
        fields.push_back(optional_number(m.voronoi_phi));
    } else {
        fields.insert(fields.end(), tolerances + 6, "");
    }
    fields.push_back(row.path);
    std::string line;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        line += (i == 0 ? "" : ",") + compare::csv_field(fields[i]);
    }
    return line + "\n";
}

std::string summary_text(const std::vector<std::string>& lines) {
    std::string text;
    const auto header = summary_header();
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

SummaryTable parse_summary(std::string_view text, const std::string& source) {
    SummaryTable table;
    const auto expected = summary_header();
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

std::string merge_summaries(const std::vector<SummaryTable>& tables) {
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
    return summary_text(lines);
}

}  // namespace sgmp::batch
