#pragma once
/// @file baseline.hpp
/// Regression baselines: the scalar metrics of a cross-validation run, each with the
/// tolerance within which a later run must reproduce it.
///
/// An entry is (candidate group, count, metric) → the group's mean over its seeds. Its
/// tolerance comes from the reference's seed-to-seed spread: the smallest tolerance of the
/// agreement rows that compared this metric with a reference group, i.e.
/// min over references of max(2·sd_reference, floor of the metric). A current value
/// passes when |current − baseline| ≤ tolerance.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sgmp/report/agreement.hpp"

namespace sgmp::report {

struct BaselineEntry {
    std::string group;
    std::size_t count = 0;
    std::string metric;
    std::string unit;
    double value = 0.0;
    double tolerance = 0.0;
    std::string tolerance_source;  // e.g. "2 sd of DEM mu=0.5 (3 packs)" or "floor"
};

/// The entries of a report, in group, count, metric order.
std::vector<BaselineEntry> baseline_entries(const Report& report);

/// The baseline file: {"provenance": ..., "rule": "...", "entries": [...]}.
nlohmann::ordered_json baseline_json(const std::vector<BaselineEntry>& entries,
                                     const nlohmann::ordered_json& provenance);

/// Reads the entries back; throws sgmp::InputError (source and reason) when the JSON is
/// not a baseline.
std::vector<BaselineEntry> parse_baseline(const nlohmann::json& json, const std::string& source);

/// Checks that two baselines were measured alike: their `provenance.parameters` (the
/// measurement options: region, g(r) bins, Q6 cut-off, …) must be equal key by key, since a
/// metric measured another way is another number. Throws sgmp::InputError naming the
/// first key that differs, or a baseline that records no parameters.
void check_measured_alike(const nlohmann::json& baseline, const std::string& baseline_source,
                          const nlohmann::json& current, const std::string& current_source);

struct RegressionRow {
    BaselineEntry baseline;
    std::optional<double> current;  // absent when the current run lacks the entry
    bool pass = false;
};

/// Compares every baseline entry with the current run's entry of the same key.
std::vector<RegressionRow> regress(const std::vector<BaselineEntry>& baseline,
                                   const std::vector<BaselineEntry>& current);

/// Table group | N | metric | baseline | current | change | tolerance | verdict; with
/// `failures_only` just the rows that failed.
std::string render_regression_table(const std::vector<RegressionRow>& rows, bool failures_only);

}  // namespace sgmp::report
