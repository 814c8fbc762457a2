#include "sgmp/compare/thesis_table.hpp"

#include "csv_line.hpp"
#include "sgmp/pack/input_error.hpp"

namespace sgmp::compare {
namespace {

constexpr const char* kHeader = "arrangement,count,runtime_s,packing_fraction,table";

double number_field(const std::string& text, const char* what, const std::string& source,
                    std::size_t line) {
    const auto value = detail::parse_csv_number<double>(text);
    if (!value) {
        throw InputError(source, line, std::string(what) + " '" + text + "' is not a number");
    }
    return *value;
}

}  // namespace

std::vector<ThesisResult> read_thesis_results(std::istream& in, const std::string& source) {
    std::string line;
    std::size_t number = 1;
    if (!std::getline(in, line) ||
        detail::split_csv_line(line) != detail::split_csv_line(kHeader)) {
        throw InputError(source, number, "expected the header '" + std::string(kHeader) + "'");
    }
    std::vector<ThesisResult> results;
    while (std::getline(in, line)) {
        ++number;
        if (line.find_first_not_of(" \t\r") == std::string::npos) {
            continue;
        }
        const auto fields = detail::split_csv_line(line);
        if (fields.size() != 5) {
            throw InputError(
                source, number,
                "expected 5 comma-separated fields, found " + std::to_string(fields.size()));
        }
        ThesisResult row;
        row.arrangement = fields[0];
        const double count = number_field(fields[1], "count", source, number);
        if (count < 1.0 || count != static_cast<double>(static_cast<std::size_t>(count))) {
            throw InputError(source, number,
                             "count '" + fields[1] + "' must be a positive integer");
        }
        row.count = static_cast<std::size_t>(count);
        row.runtime_seconds = number_field(fields[2], "runtime_s", source, number);
        row.packing_fraction = number_field(fields[3], "packing_fraction", source, number);
        row.table = fields[4];
        results.push_back(std::move(row));
    }
    return results;
}

std::optional<ThesisResult> find_thesis_result(const std::vector<ThesisResult>& results,
                                               const std::string& arrangement, std::size_t count) {
    for (const auto& row : results) {
        if (row.arrangement == arrangement && row.count == count) {
            return row;
        }
    }
    return std::nullopt;
}

}  // namespace sgmp::compare
