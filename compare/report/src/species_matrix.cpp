#include "sgmp/report/species_matrix.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "matrix_table.hpp"
#include "sgmp/report/crossval_render.hpp"
#include "sgmp/report/species_rows.hpp"

namespace sgmp::report {
namespace {

/// The per-species rows' names and labels, in the order the comparisons first hold them.
std::vector<const MetricRow*> species_columns(const CrossValidation& cv) {
    std::vector<const MetricRow*> columns;
    for (const HeadlineRow& row : cv.rows) {
        for (const HeadlineVerdict& against : row.against) {
            for (const MetricRow& m : against.rows) {
                const bool known =
                    std::any_of(columns.begin(), columns.end(),
                                [&](const MetricRow* c) { return c->name == m.name; });
                if (is_species_metric(m.name) && !known) {
                    columns.push_back(&m);
                }
            }
        }
    }
    return columns;
}

/// The row of `name` in a comparison, or nullptr when it lacks one.
const MetricRow* find_row(const HeadlineVerdict& against, const std::string& name) {
    const auto it = std::find_if(against.rows.begin(), against.rows.end(),
                                 [&](const MetricRow& m) { return m.name == name; });
    return it == against.rows.end() ? nullptr : &*it;
}

}  // namespace

void species_matrix_markdown(std::ostringstream& md, const CrossValidation& cv) {
    const std::vector<const MetricRow*> columns = species_columns(cv);
    if (columns.empty()) {
        return;
    }
    md << "\n## Per-species verdict matrix\n\n";
    md << "The blend's per-species rows, judged like every scalar on their declared margins "
          "(compare/README.md): ✓ agree, ✗ differ, ◌ inconclusive, · not compared or "
          "information only. Columns:\n\n";
    for (std::size_t c = 0; c < columns.size(); ++c) {
        md << "- " << c + 1 << ": " << columns[c]->label << " (" << columns[c]->unit << ")\n";
    }
    std::vector<std::string> numbers;
    for (std::size_t c = 0; c < columns.size(); ++c) {
        numbers.push_back(std::to_string(c + 1));
    }
    md << "\n";
    detail::matrix_header(md, numbers);
    for (const std::size_t n : cv.counts) {
        detail::count_header_row(md, n, columns.size());
        for (const HeadlineRow& row : cv.rows) {
            if (row.count != n) {
                continue;
            }
            for (std::size_t r = 0; r < row.against.size(); ++r) {
                const HeadlineVerdict& against = row.against[r];
                if (against.rows.empty()) {
                    continue;  // no pours of that class at this count
                }
                md << "| " << row.group << " | " << cv.references[r] << " |";
                std::size_t agree = 0;
                std::size_t judged = 0;
                for (const MetricRow* column : columns) {
                    const MetricRow* m = find_row(against, column->name);
                    const Verdict v = m != nullptr ? m->verdict : Verdict::Info;
                    agree += v == Verdict::Agree ? 1 : 0;
                    judged += v == Verdict::Info ? 0 : 1;
                    md << " " << verdict_mark(v) << " |";
                }
                md << " " << detail::agree_cell(agree, judged) << " |\n";
            }
        }
    }
}

}  // namespace sgmp::report
