#pragma once
/// @file parameter_table.hpp
/// A request struct's parameter table: one row per parameter, with its name, how its value
/// is typed, parsed from text, formatted as text and checked, and its help. The command
/// line, batch grids, Python keywords, config files, the pack header's record and the
/// request's validation all iterate over the same rows, so each parameter is spelled once.
///
/// Names are snake_case, as pack headers, batch summaries, Python keywords and config files
/// spell them; the command line spells `name` as `--name` with dashes (option_name).
/// Formatting is exact: a number is written as the shortest text that reads back to the
/// same double (format_number), so parse(format(r)) gives r's value again.
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/option_rules.hpp"

namespace sgmp {

/// How a parameter's value is typed: it decides how a front end converts its own values
/// (a Python float, a batch grid entry) to the row's text.
enum class ValueKind {
    Number,   ///< a real number ("must be a number" when the text is not one)
    Integer,  ///< a whole number
    Choice,   ///< one name of a name table
    List,     ///< comma-separated items (its batch values are given one per option)
    Text,     ///< any other text
};

/// One parameter of the struct `Request`; `Context` is what its check needs beyond the
/// request (for example a diameter the request implies).
template <class Request, class Context>
struct ParameterRow {
    std::string name;   ///< snake_case
    std::string group;  ///< which part of the request it belongs to (rows are recorded by group)
    /// The header's key when it is not `name` (a unit suffix: `youngs_modulus_pa`).
    std::string header;
    ValueKind kind = ValueKind::Number;
    std::string help;
    /// What a value must look like, said when `parse` refuses it ("must be a number").
    std::string rule;
    /// Sets the value in the request; false when the text is not a value of this parameter.
    std::function<bool(Request&, std::string_view)> parse;
    /// The value as text, as the pack header records it.
    std::function<std::string(const Request&)> format;
    /// Throws ParameterError (name, value, rule) when the value breaks its rule; empty when
    /// parsing is the only rule.
    std::function<void(const Request&, const Context&)> check{};
    /// Whether the header records the value (empty: always).
    std::function<bool(const Request&)> recorded{};
    /// The default value as text (format of a default-constructed request); set by the
    /// table with fill_defaults.
    std::string default_text;
    /// A value must be given: there is no default (the command line requires it).
    bool required = false;
    /// Unset by default: an empty value leaves the request as it is.
    bool unset_by_default = false;
};

/// Sets every row's default_text from a default-constructed request.
template <class Request, class Context>
void fill_defaults(std::vector<ParameterRow<Request, Context>>& rows) {
    static const Request defaults;
    for (auto& row : rows) {
        row.default_text = row.format(defaults);
    }
}

/// The header key of a row.
template <class Row>
const std::string& header_key(const Row& row) {
    return row.header.empty() ? row.name : row.header;
}

/// Records the rows of `group` that `request` records, in table order, as
/// header_key(row) = format(request).
template <class Request, class Context>
void record_rows(const std::vector<ParameterRow<Request, Context>>& rows, const Request& request,
                 std::string_view group, Metadata& metadata) {
    for (const auto& row : rows) {
        if (row.group == group && (!row.recorded || row.recorded(request))) {
            metadata.set(header_key(row), row.format(request));
        }
    }
}

/// Runs the checks of the rows of `group` (every row when `group` is empty), in table order.
template <class Request, class Context>
void check_rows(const std::vector<ParameterRow<Request, Context>>& rows, const Request& request,
                std::string_view group, const Context& context) {
    for (const auto& row : rows) {
        if ((group.empty() || row.group == group) && row.check) {
            row.check(request, context);
        }
    }
}

/// The command line's spelling of a snake_case name: "--phi-target".
inline std::string option_name(std::string_view name) {
    std::string option = "--" + std::string(name);
    std::replace(option.begin() + 2, option.end(), '_', '-');
    return option;
}

/// The row named `name` (snake_case, or kebab-case with or without leading dashes), or
/// nullptr.
template <class Row>
const Row* find_row(const std::vector<Row>& rows, std::string_view name) {
    std::string key(name.substr(name.rfind("--") == 0 ? 2 : 0));
    std::replace(key.begin(), key.end(), '-', '_');
    const auto found =
        std::find_if(rows.begin(), rows.end(), [&](const Row& row) { return row.name == key; });
    return found == rows.end() ? nullptr : &*found;
}

/// The whole text as a double (std::from_chars: "1e3", "inf" and "nan" read; "1,5" does not).
inline std::optional<double> parse_real(std::string_view text) {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value);
    if (text.empty() || result.ec != std::errc() || result.ptr != end) {
        return std::nullopt;
    }
    return value;
}

/// The whole text as a whole number of type T. A number beyond T's range is clamped to it,
/// so the row's check, not a wrap, refuses it.
template <class T>
std::optional<T> parse_whole(std::string_view text) {
    static_assert(std::is_integral_v<T>);
    long long value = 0;
    const char* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value);
    if (text.empty() || result.ptr != end) {
        return std::nullopt;
    }
    if (result.ec == std::errc::result_out_of_range) {
        return text.front() == '-' ? std::numeric_limits<T>::min() : std::numeric_limits<T>::max();
    }
    if (result.ec != std::errc()) {
        return std::nullopt;
    }
    if (std::is_unsigned_v<T> && value < 0) {
        return std::nullopt;
    }
    using Wide = std::conditional_t<std::is_unsigned_v<T>, unsigned long long, long long>;
    const Wide wide = static_cast<Wide>(value);
    return static_cast<T>(std::clamp<Wide>(wide, static_cast<Wide>(std::numeric_limits<T>::min()),
                                           static_cast<Wide>(std::numeric_limits<T>::max())));
}

/// The value type of a row's member: T for T and for std::optional<T> (a member that may
/// be left unset, which formats as "").
template <class T>
struct RowValue {
    using type = T;
};
template <class T>
struct RowValue<std::optional<T>> {
    using type = T;
};

/// A row of a real-valued member reached by `member(request)` (a generic lambda returning a
/// reference), refused unless the whole text is a number.
template <class Request, class Context, class Member>
ParameterRow<Request, Context> number_row(
    std::string name, std::string group, Member member, std::string help,
    std::function<void(const Request&, const Context&)> check = {}) {
    ParameterRow<Request, Context> row;
    row.name = std::move(name);
    row.group = std::move(group);
    row.kind = ValueKind::Number;
    row.help = std::move(help);
    row.rule = "must be a number";
    row.parse = [member](Request& r, std::string_view text) {
        const auto value = parse_real(text);
        if (value) {
            member(r) = *value;
        }
        return value.has_value();
    };
    row.format = [member](const Request& r) {
        using T = typename RowValue<std::remove_cvref_t<decltype(member(r))>>::type;
        const std::optional<T> value = member(r);
        return value ? format_number(*value) : std::string{};
    };
    row.check = std::move(check);
    return row;
}

/// A row of a whole-number member (of its own integer type) reached by `member(request)`.
template <class Request, class Context, class Member>
ParameterRow<Request, Context> whole_row(
    std::string name, std::string group, Member member, std::string help,
    std::function<void(const Request&, const Context&)> check = {}) {
    ParameterRow<Request, Context> row;
    row.name = std::move(name);
    row.group = std::move(group);
    row.kind = ValueKind::Integer;
    row.help = std::move(help);
    row.rule = "must be a whole number";
    row.parse = [member](Request& r, std::string_view text) {
        using T = typename RowValue<std::remove_reference_t<decltype(member(r))>>::type;
        const auto value = parse_whole<T>(text);
        if (value) {
            member(r) = *value;
        }
        return value.has_value();
    };
    row.format = [member](const Request& r) {
        using T = typename RowValue<std::remove_cvref_t<decltype(member(r))>>::type;
        const std::optional<T> value = member(r);
        return value ? std::to_string(*value) : std::string{};
    };
    row.check = std::move(check);
    return row;
}

/// A row of a member holding one name of a name table `table()` (name_table.hpp), e.g. the
/// sides or a fraction basis.
template <class Request, class Context, class Member, class Table>
ParameterRow<Request, Context> choice_row(std::string name, std::string group, Member member,
                                          Table table, std::string help) {
    ParameterRow<Request, Context> row;
    row.name = std::move(name);
    row.group = std::move(group);
    row.kind = ValueKind::Choice;
    row.help = std::move(help);
    row.rule = "must be one of " + table().choices();
    row.parse = [member, table](Request& r, std::string_view text) {
        const auto value = table().parse(text);
        if (value) {
            member(r) = *value;
        }
        return value.has_value();
    };
    row.format = [member, table](const Request& r) { return std::string(table().name(member(r))); };
    return row;
}

/// A row of a seed (`std::uint64_t seed` of the request): decimal digits from 0 to 2⁶⁴ − 1,
/// refused rather than wrapped (seed_rule).
template <class Request, class Context>
ParameterRow<Request, Context> seed_row(std::string group, std::string help) {
    ParameterRow<Request, Context> row;
    row.name = "seed";
    row.group = std::move(group);
    row.kind = ValueKind::Integer;
    row.help = std::move(help);
    row.rule = seed_rule("");
    row.parse = [](Request& r, std::string_view text) {
        if (!seed_rule(text).empty()) {
            return false;
        }
        std::from_chars(text.data(), text.data() + text.size(), r.seed);
        return true;
    };
    row.format = [](const Request& r) { return std::to_string(r.seed); };
    return row;
}

}  // namespace sgmp
