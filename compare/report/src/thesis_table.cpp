#include "sgmp/report/thesis_table.hpp"

#include <algorithm>
#include <functional>

#include "sgmp/pack/csv_fields.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/line_reader.hpp"

namespace sgmp::report {
namespace {

using Fields = std::vector<std::string>;

/// Reads a CSV with exactly `header`, calling `row` with the fields of every non-blank line
/// and its number.
void read_rows(std::istream& in, const std::string& source, const std::string& header,
               const std::function<void(const Fields&, std::size_t)>& row) {
    LineReader reader(in, source);
    std::string line;
    const Fields columns = split_csv_line(header);
    if (!reader.next(line) || split_csv_line(line) != columns) {
        throw InputError(source, 1, "expected the header '" + header + "'");
    }
    while (reader.next(line)) {
        if (line.find_first_not_of(" \t") == std::string::npos) {
            continue;
        }
        const Fields fields = split_csv_line(line);
        if (fields.size() != columns.size()) {
            throw reader.error("expected " + std::to_string(columns.size()) +
                               " comma-separated fields, found " + std::to_string(fields.size()));
        }
        row(fields, reader.line_number());
    }
}

double number_field(const std::string& text, const char* what, const std::string& source,
                    std::size_t line) {
    const auto value = parse_csv_number<double>(text);
    if (!value) {
        throw InputError(source, line, std::string(what) + " '" + text + "' is not a number");
    }
    return *value;
}

std::size_t count_field(const std::string& text, const std::string& source, std::size_t line) {
    const auto value = parse_csv_number<std::size_t>(text);
    if (!value || *value == 0) {
        throw InputError(source, line, "count '" + text + "' must be a positive integer");
    }
    return *value;
}

template <class Row>
std::optional<Row> find_row(const std::vector<Row>& rows, const std::string& arrangement,
                            std::size_t count) {
    const auto found = std::find_if(rows.begin(), rows.end(), [&](const Row& row) {
        return row.arrangement == arrangement && row.count == count;
    });
    return found == rows.end() ? std::nullopt : std::optional<Row>(*found);
}

}  // namespace

std::vector<ThesisResult> read_thesis_results(std::istream& in, const std::string& source) {
    std::vector<ThesisResult> results;
    read_rows(in, source, "arrangement,count,runtime_s,packing_fraction,table",
              [&](const Fields& f, std::size_t line) {
                  results.push_back(
                      ThesisResult{f[0], count_field(f[1], source, line),
                                   number_field(f[2], "runtime_s", source, line),
                                   number_field(f[3], "packing_fraction", source, line), f[4]});
              });
    return results;
}

std::vector<ThesisStart> read_thesis_starts(std::istream& in, const std::string& source) {
    std::vector<ThesisStart> starts;
    read_rows(in, source, "arrangement,count,grid,starting_height,table",
              [&](const Fields& f, std::size_t line) {
                  starts.push_back(ThesisStart{f[0], count_field(f[1], source, line), f[2],
                                               number_field(f[3], "starting_height", source, line),
                                               f[4]});
              });
    return starts;
}

std::optional<ThesisResult> find_thesis_result(const std::vector<ThesisResult>& results,
                                               const std::string& arrangement, std::size_t count) {
    return find_row(results, arrangement, count);
}

std::optional<ThesisStart> find_thesis_start(const std::vector<ThesisStart>& starts,
                                             const std::string& arrangement, std::size_t count) {
    return find_row(starts, arrangement, count);
}

}  // namespace sgmp::report
