#include "sgmp/report/baseline.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <tuple>

#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/pack/input_error.hpp"

namespace sgmp::report {

using metrics::kSchemaVersion;
namespace {

using Key = std::tuple<std::string, std::size_t, std::string>;

Key key_of(const BaselineEntry& e) {
    return {e.group, e.count, e.metric};
}

std::string number(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

}  // namespace

std::vector<BaselineEntry> baseline_entries(const Report& report) {
    std::map<Key, BaselineEntry> entries;
    std::vector<Key> order;
    for (const auto& c : report.comparisons) {
        for (const auto& row : c.rows) {
            if (row.kind != MetricKind::Scalar) {
                continue;  // curves are judged by distance, not by a value to keep
            }
            const Key key{c.candidate, c.count, row.name};
            const std::string source = "declared margin";
            auto found = entries.find(key);
            if (found == entries.end()) {
                order.push_back(key);
                entries.emplace(key, BaselineEntry{c.candidate, c.count, row.name, row.unit,
                                                   row.candidate_mean, row.tolerance, source});
            } else if (row.tolerance < found->second.tolerance) {
                found->second.tolerance = row.tolerance;
                found->second.tolerance_source = source;
            }
        }
    }
    std::vector<BaselineEntry> result;
    for (const auto& key : order) {
        result.push_back(entries.at(key));
    }
    return result;
}

nlohmann::ordered_json baseline_json(const std::vector<BaselineEntry>& entries,
                                     const nlohmann::ordered_json& provenance) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const auto& e : entries) {
        list.push_back({{"group", e.group},
                        {"count", e.count},
                        {"metric", e.metric},
                        {"unit", e.unit},
                        {"value", e.value},
                        {"tolerance", e.tolerance},
                        {"tolerance_source", e.tolerance_source}});
    }
    return {{"schema_version", kSchemaVersion},
            {"provenance", provenance},
            {"rule",
             "value: the candidate group's mean over its seeds; tolerance: the metric's declared "
             "equivalence margin (compare/README.md, Margins); a later run passes when "
             "|current - value| <= tolerance"},
            {"entries", list}};
}

namespace {

/// The measurement parameters a baseline records, or an InputError naming its file.
const nlohmann::json& measurement_parameters(const nlohmann::json& json,
                                             const std::string& source) {
    const auto provenance = json.find("provenance");
    if (provenance == json.end() || !provenance->is_object() ||
        !provenance->contains("parameters") || !(*provenance)["parameters"].is_object()) {
        throw InputError(source, 0,
                         "records no provenance.parameters, so how its metrics were measured is "
                         "unknown; make it again with this version's crossval");
    }
    return (*provenance)["parameters"];
}

}  // namespace

void check_measured_alike(const nlohmann::json& baseline, const std::string& baseline_source,
                          const nlohmann::json& current, const std::string& current_source) {
    const nlohmann::json& was = measurement_parameters(baseline, baseline_source);
    const nlohmann::json& now = measurement_parameters(current, current_source);
    nlohmann::json keys = nlohmann::json::object();
    for (const auto& [key, value] : was.items()) {
        keys[key] = true;
    }
    for (const auto& [key, value] : now.items()) {
        keys[key] = true;
    }
    for (const auto& [key, unused] : keys.items()) {
        const std::string before = was.contains(key) ? was[key].dump() : "nothing";
        const std::string after = now.contains(key) ? now[key].dump() : "nothing";
        if (before != after) {
            throw InputError(current_source, 0,
                             "measured with " + key + " " + after + ", the baseline " +
                                 baseline_source + " with " + before +
                                 "; regress compares metrics measured alike");
        }
    }
}

std::vector<BaselineEntry> parse_baseline(const nlohmann::json& json, const std::string& source) {
    if (!json.is_object() || !json.contains("entries") || !json["entries"].is_array()) {
        throw InputError(source, 0, "not a baseline: no \"entries\" array");
    }
    const auto version = json.find("schema_version");
    if (version == json.end() || !version->is_number_unsigned() || *version < 1 ||
        *version > kSchemaVersion) {
        throw InputError(source, 0,
                         "schema_version " + (version == json.end() ? "missing" : version->dump()) +
                             ": must be a whole number from 1 to " +
                             std::to_string(kSchemaVersion));
    }
    std::vector<BaselineEntry> entries;
    std::map<Key, std::size_t> first_of;
    std::size_t index = 0;
    for (const auto& item : json["entries"]) {
        try {
            BaselineEntry e;
            const auto field = [&](const char* key) -> const nlohmann::json& {
                if (!item.is_object() || !item.contains(key)) {
                    throw std::invalid_argument(std::string("it has no '") + key + "'");
                }
                return item[key];
            };
            const auto text = [&](const char* key) {
                if (!field(key).is_string()) {
                    throw std::invalid_argument(std::string("'") + key + "' must be a string");
                }
                return field(key).get<std::string>();
            };
            const auto number = [&](const char* key) {
                if (!field(key).is_number()) {
                    throw std::invalid_argument(std::string("'") + key + "' must be a number");
                }
                return field(key).get<double>();
            };
            e.group = text("group");
            // A whole number as JSON holds it: a float (1e50) has no exact count, and its
            // conversion would be undefined.
            const auto& count = field("count");
            if (!count.is_number_unsigned()) {
                throw std::invalid_argument("count " + count.dump() +
                                            " must be a whole number >= 0");
            }
            e.count = count.get<std::size_t>();
            e.metric = text("metric");
            e.unit = item.contains("unit") ? text("unit") : "";
            e.value = number("value");
            e.tolerance = number("tolerance");
            e.tolerance_source = item.contains("tolerance_source") ? text("tolerance_source") : "";
            if (!std::isfinite(e.value) || !std::isfinite(e.tolerance) || e.tolerance < 0.0) {
                throw std::invalid_argument("value and tolerance must be finite, tolerance >= 0");
            }
            const auto [seen, fresh] = first_of.emplace(key_of(e), index);
            if (!fresh) {
                throw std::invalid_argument("it repeats group, count and metric of entry " +
                                            std::to_string(seen->second) +
                                            " (which one would be checked?)");
            }
            entries.push_back(std::move(e));
        } catch (const std::exception& error) {
            throw InputError(source, 0,
                             "entry " + std::to_string(index) + " is malformed: " + error.what());
        }
        ++index;
    }
    return entries;
}

std::vector<RegressionRow> regress(const std::vector<BaselineEntry>& baseline,
                                   const std::vector<BaselineEntry>& current) {
    std::map<Key, const BaselineEntry*> now;
    for (const auto& e : current) {
        now[key_of(e)] = &e;
    }
    std::vector<RegressionRow> rows;
    for (const auto& e : baseline) {
        RegressionRow row;
        row.baseline = e;
        const auto found = now.find(key_of(e));
        if (found != now.end()) {
            row.current = found->second->value;
            row.pass = std::abs(*row.current - e.value) <= e.tolerance;
        }
        rows.push_back(row);
    }
    return rows;
}

std::string render_regression_table(const std::vector<RegressionRow>& rows, bool failures_only) {
    std::ostringstream out;
    char line[320];
    std::snprintf(line, sizeof line, "%-16s %6s %-20s %12s %12s %12s %12s  %s\n", "group", "N",
                  "metric", "baseline", "current", "change", "tolerance", "verdict");
    out << line;
    for (const auto& row : rows) {
        if (failures_only && row.pass) {
            continue;
        }
        const auto& b = row.baseline;
        std::snprintf(line, sizeof line, "%-16s %6zu %-20s %12s %12s %12s %12s  %s\n",
                      b.group.c_str(), b.count, b.metric.c_str(), number(b.value).c_str(),
                      row.current ? number(*row.current).c_str() : "missing",
                      row.current ? number(*row.current - b.value).c_str() : "-",
                      number(b.tolerance).c_str(), row.pass ? "pass" : "FAIL");
        out << line;
    }
    return out.str();
}

}  // namespace sgmp::report
