#pragma once
/// @file csv_fields.hpp
/// Fields of one CSV line (RFC 4180 quoting) and strict numbers in them: what every CSV
/// writer and reader of the testbed shares.

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace sgmp {

/// The field as written: quoted, with doubled quotes, when it holds a comma, a quote or a
/// line break (RFC 4180); as it is otherwise.
inline std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) {
        return text;
    }
    std::string quoted = "\"";
    for (const char c : text) {
        quoted += c;
        if (c == '"') {
            quoted += '"';
        }
    }
    return quoted + "\"";
}

/// Fields of one CSV line (RFC 4180): a field may be double-quoted, and then holds commas
/// and doubled quotes ("" for "). nullopt for a line with an unterminated quote or text
/// after a closing quote.
inline std::optional<std::vector<std::string>> split_quoted_csv_line(std::string_view line) {
    if (!line.empty() && line.back() == '\r') {
        line.remove_suffix(1);
    }
    std::vector<std::string> fields;
    std::size_t pos = 0;
    while (true) {
        std::string field;
        if (pos < line.size() && line[pos] == '"') {
            ++pos;
            while (true) {
                const std::size_t quote = line.find('"', pos);
                if (quote == std::string_view::npos) {
                    return std::nullopt;
                }
                field.append(line.substr(pos, quote - pos));
                pos = quote + 1;
                if (pos < line.size() && line[pos] == '"') {
                    field.push_back('"');
                    ++pos;
                    continue;
                }
                break;
            }
            if (pos < line.size() && line[pos] != ',') {
                return std::nullopt;
            }
        } else {
            const std::size_t comma = line.find(',', pos);
            const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
            field.assign(line.substr(pos, end - pos));
            pos = end;
        }
        fields.push_back(std::move(field));
        if (pos >= line.size()) {
            return fields;
        }
        ++pos;  // the comma
    }
}

/// Fields of a CSV line as split_quoted_csv_line; a malformed quote leaves the line as
/// one field (which then fails the caller's field count).
inline std::vector<std::string> split_csv_line(std::string_view line) {
    auto fields = split_quoted_csv_line(line);
    if (!fields) {
        return {std::string(line)};
    }
    return std::move(*fields);
}

/// The whole field as a number (integer or floating point); nullopt when it is not one,
/// or when it is a floating-point field holding nan or inf.
template <class Number>
std::optional<Number> parse_csv_number(const std::string& text) {
    Number value{};
    const auto* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value);
    if (text.empty() || result.ec != std::errc() || result.ptr != end) {
        return std::nullopt;
    }
    if constexpr (std::is_floating_point_v<Number>) {
        if (!std::isfinite(value)) {
            return std::nullopt;
        }
    }
    return value;
}

}  // namespace sgmp
