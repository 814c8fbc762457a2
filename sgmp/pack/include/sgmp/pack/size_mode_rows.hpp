#pragma once
/// @file size_mode_rows.hpp
/// The parameter rows of a size distribution (size_modes.hpp), one definition for every
/// parameter table that takes one (`sgmp pack`'s and `sgmp-reference pour`'s): `size_modes`
/// (relative-diameter:fraction[:density] items) and `size_distribution` (its text form,
/// lognormal:…; a CSV file is read by the front end). Checks, `recorded` and the help are
/// the caller's.
#include <string>
#include <string_view>
#include <utility>

#include "sgmp/pack/parameter_table.hpp"
#include "sgmp/pack/size_modes.hpp"

namespace sgmp {

/// `size_modes`: the member `modes(request)` (a std::vector<SizeMode>&).
template <class Request, class Context, class Modes>
ParameterRow<Request, Context> size_modes_row(std::string group, std::string help, Modes modes) {
    ParameterRow<Request, Context> row;
    row.name = "size_modes";
    row.group = std::move(group);
    row.kind = ValueKind::List;
    row.help = std::move(help);
    row.rule = "must be positive diameter:fraction[:density] items, e.g. 1:0.7,0.5:0.3";
    row.parse = [modes](Request& r, std::string_view text) {
        auto parsed = parse_size_modes(text);
        if (parsed) {
            modes(r) = std::move(*parsed);
        }
        return parsed.has_value();
    };
    row.format = [modes](const Request& r) { return size_modes_to_string(modes(r)); };
    return row;
}

/// `size_distribution`: sets `modes(request)` from a lognormal text and keeps the text in
/// `text(request)` (a std::string&); recorded when given, unset by default.
template <class Request, class Context, class Modes, class Text>
ParameterRow<Request, Context> size_distribution_row(std::string group, std::string help,
                                                     Modes modes, Text text) {
    ParameterRow<Request, Context> row;
    row.name = "size_distribution";
    row.group = std::move(group);
    row.kind = ValueKind::Text;
    row.help = std::move(help);
    row.rule = "must be lognormal:MEDIAN:SIGMA[:CLASSES[:QLO:QHI]]";
    // The text form only: a file is opened by the front end, which gives its text to
    // parse_size_distribution_csv (algorithm code opens no file).
    row.parse = [modes, text](Request& r, std::string_view value) {
        if (!is_lognormal(value)) {
            return false;
        }
        modes(r) = lognormal_modes(value);
        text(r) = std::string(value);
        return true;
    };
    row.format = [text](const Request& r) { return text(r); };
    row.recorded = [text](const Request& r) { return !text(r).empty(); };
    row.unset_by_default = true;
    return row;
}

}  // namespace sgmp
