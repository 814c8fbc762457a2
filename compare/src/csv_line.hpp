#pragma once
// Private helper: one line of a simple CSV (no quoting) split at commas.

#include <string>
#include <string_view>
#include <vector>

namespace sgmp::compare::detail {

inline std::vector<std::string> split_csv_line(std::string_view line) {
    if (!line.empty() && line.back() == '\r') {
        line.remove_suffix(1);
    }
    std::vector<std::string> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        fields.emplace_back(line.substr(
            start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) {
            return fields;
        }
        start = comma + 1;
    }
}

}  // namespace sgmp::compare::detail
