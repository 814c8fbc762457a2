#pragma once
/// @file pack_parameter_rows.hpp
/// What the pack request's rows (pack_parameters.cpp) and the relaxation's rows
/// (pack_parameter_relax_rows.cpp) are built with: row makers and range checks. Internal to
/// the engine.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "sgmp/engine/pack_parameters.hpp"
#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/parameter_error.hpp"

namespace sgmp::engine::pack_rows {

using Row = PackParameter;
using Check = std::function<void(const PackRequest&, const PackCheckContext&)>;

[[noreturn]] inline void refuse(const char* name, std::string value, std::string rule) {
    throw ParameterError(name, std::move(value), std::move(rule));
}

template <class Member>
Row number(std::string name, std::string group, Member member, std::string help, Check check) {
    return number_row<PackRequest, PackCheckContext>(std::move(name), std::move(group), member,
                                                     std::move(help), std::move(check));
}

template <class Member>
Row whole(std::string name, std::string group, Member member, std::string help, Check check) {
    return whole_row<PackRequest, PackCheckContext>(std::move(name), std::move(group), member,
                                                    std::move(help), std::move(check));
}

/// A member holding one name of a name table `table()` (parameter_table.hpp).
template <class Member, class Table>
Row choice(std::string name, std::string group, Member member, Table table, std::string help) {
    return choice_row<PackRequest, PackCheckContext>(std::move(name), std::move(group), member,
                                                     table, std::move(help));
}

/// Checks `low ≤ value ≤ high` (NaN fails).
template <class Member>
Check in_range(const char* name, Member member, double low, double high, std::string rule) {
    return [=](const PackRequest& r, const PackCheckContext&) {
        const double v = static_cast<double>(member(r));
        if (!(v >= low) || !(v <= high)) {
            refuse(name, format_number(v), rule);
        }
    };
}

template <class Member>
Check at_least_one(const char* name, Member member) {
    return [=](const PackRequest& r, const PackCheckContext&) {
        if (member(r) < 1) {
            refuse(name, std::to_string(member(r)), "must be at least 1");
        }
    };
}

/// Appends the relaxation's rows (pack_parameter_relax_rows.cpp).
void add_relax_rows(std::vector<Row>& rows);

}  // namespace sgmp::engine::pack_rows
