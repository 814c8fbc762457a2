#include "sgmp/report/dem_parameters.hpp"

#include <algorithm>
#include <string_view>

#include "sgmp/reference/pour_parameters.hpp"

namespace sgmp::report {
namespace {

/// Header keys shown, in the pour table's order.
std::vector<std::string> shown_keys() {
    std::vector<std::string> keys;
    for (const auto& row : reference::pour_parameters()) {
        const bool shown = row.group == "start" || row.group == "material" ||
                           row.group == "numerics" ||
                           (row.group == "identity" && row.name != "seed");
        const std::string& key = header_key(row);
        if (shown && std::find(keys.begin(), keys.end(), key) == keys.end()) {
            keys.push_back(key);
        }
    }
    keys.insert(keys.begin(), "start");  // cloud or an arrangement, before its parameters
    keys.emplace_back("contact_model");
    keys.emplace_back("liggghts_version");
    return keys;
}

std::string value_of(const PackSummary& pack, std::string_view key) {
    for (const auto& [k, v] : pack.provenance) {
        if (k == key) {
            return v;
        }
    }
    return {};
}

bool is_pour(const PackSummary& pack) {
    return value_of(pack, "generator") == "liggghts";
}

/// One cell: the distinct values of `key` over the pours, as described in the header.
std::string cell(const Group& group, const std::string& key) {
    std::vector<std::string> distinct;
    for (const auto& pack : group.packs) {
        const std::string v = value_of(pack, key);
        if (is_pour(pack) && !v.empty() &&
            std::find(distinct.begin(), distinct.end(), v) == distinct.end()) {
            distinct.push_back(v);
        }
    }
    if (distinct.empty()) {
        return "—";
    }
    if (distinct.size() <= 3) {
        std::string text;
        for (const auto& v : distinct) {
            text += (text.empty() ? "" : " / ") + v;
        }
        return text;
    }
    return std::to_string(distinct.size()) + " values";
}

}  // namespace

DemParameterTable dem_parameter_table(const Report& report,
                                      const std::vector<std::string>& references) {
    DemParameterTable table;
    std::vector<const Group*> groups;
    for (const auto& label : references) {
        for (const auto& group : report.groups) {
            if (group.label == label &&
                std::any_of(group.packs.begin(), group.packs.end(), is_pour)) {
                table.classes.push_back(label);
                groups.push_back(&group);
                break;
            }
        }
    }
    if (groups.empty()) {
        return table;
    }
    for (const auto& key : shown_keys()) {
        std::vector<std::string> row;
        for (const Group* group : groups) {
            row.push_back(cell(*group, key));
        }
        if (std::any_of(row.begin(), row.end(), [](const std::string& v) { return v != "—"; })) {
            table.keys.push_back(key);  // a key no pour records is left out
            table.values.push_back(std::move(row));
        }
    }
    return table;
}

}  // namespace sgmp::report
