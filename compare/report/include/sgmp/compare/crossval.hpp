#pragma once
/// @file crossval.hpp
/// The cross-validation model of an agreement report: SGMP modes (candidate groups) against
/// DEM friction classes (reference groups). Per mode and count, the headline metrics
/// (headline_metrics()) with their verdicts against each class; the runtime of a pack beside
/// the DEM pour of the same N and beside the thesis' runtime; the height of the starting
/// arrangement beside the thesis' (Tables 6.2, 7.2, 8.2); and per class the mode that
/// stands in for it best. The views are in crossval_render.hpp.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sgmp/compare/agreement.hpp"
#include "sgmp/compare/hard_sphere_limit.hpp"
#include "sgmp/compare/manifest.hpp"
#include "sgmp/compare/thesis_table.hpp"

namespace sgmp::compare {

/// Metric keys of the headline, in column order.
const std::vector<std::string>& headline_metrics();

/// One candidate group at one count against one reference group.
struct HeadlineVerdict {
    std::string reference;
    std::vector<MetricRow> rows;  // every metric of the comparison, metric_rules() order
    std::optional<double> reference_seconds;  // mean wall seconds of the reference's packs
    std::optional<double> speedup;            // reference_seconds / candidate seconds

    [[nodiscard]] const MetricRow& row(const std::string& name) const;
};

struct HeadlineRow {
    std::string group;
    std::size_t count = 0;
    std::size_t packs = 0;
    std::optional<double> seconds;  // mean wall seconds per pack
    double diameter = 0.0;
    std::vector<HeadlineVerdict> against;  // in reference order
    std::optional<ThesisResult> thesis;
    std::optional<double> thesis_speedup;  // thesis runtime / seconds
    std::optional<double> start_height;    // mean `start_height` key of the packs
    std::optional<ThesisStart> thesis_start;

    /// Candidate mean of a scalar metric (from the first comparison).
    [[nodiscard]] double value(const std::string& name) const;
};

/// How well one mode stands in for one class, over every count and judged metric.
struct StandIn {
    std::string candidate;
    std::string reference;
    std::size_t agree = 0;
    std::size_t differ = 0;
    std::size_t inconclusive = 0;
    std::optional<double> speedup;  // at the largest count compared
    std::size_t speedup_count = 0;
    /// The worst differing verdict: metric label, count and ratio.
    std::string worst_metric;
    std::size_t worst_count = 0;
    double worst_ratio = 0.0;

    [[nodiscard]] bool stands_in() const { return differ == 0 && agree > 0; }
};

struct CrossValidation {
    std::vector<std::string> candidates;  // group labels in manifest order
    std::vector<std::string> references;
    std::vector<std::size_t> counts;  // every count compared, ascending
    std::vector<HeadlineRow> rows;    // by candidate group, then count
    std::vector<StandIn> stand_ins;   // by reference, then candidate (best first)
};

/// The thesis' published tables (either may be empty).
struct ThesisTables {
    std::vector<ThesisResult> results;
    std::vector<ThesisStart> starts;
};

/// Builds the headline from `report` (which must compare every candidate group with every
/// reference group), the manifest (for runtimes) and the thesis' tables.
CrossValidation cross_validate(const Report& report, const std::vector<ManifestEntry>& manifest,
                               const ThesisTables& thesis);

/// The groups of a manifest and what to compare: every candidate against every reference;
/// references are the classes; a `variant` group (`role` variant, `group` naming its
/// reference) is the reference's model-spread set and is compared with nothing; a `stiff`
/// group (the reference's pours settled again at stiffer contacts) is the model-spread set
/// of a reference without a variant group, and gives the reference's hard-sphere limit
/// (add_hard_sphere_limits).
struct GroupPlan {
    std::vector<std::string> labels;
    std::vector<std::vector<std::string>> paths;  // per label; empty for a derived group
    ReportPlan plan;
    std::vector<std::size_t> candidates;                     // group indices
    std::vector<std::pair<std::size_t, std::size_t>> stiff;  // (reference, its stiff group)
};
GroupPlan plan_groups(const std::vector<ManifestEntry>& manifest);

/// Appends to `groups` (the measured groups of `plan`, in its order) the hard-sphere limit
/// of every reference with a stiff group (hard_sphere_limit.hpp), and plans it as a
/// reference of its own: every candidate is compared with it; its model spread is its
/// distance from the stiff pours (the limit is known no better than its last extrapolation
/// step); its runtime is the pours' (derived_from); and the limits form a class set of their
/// own, so a limit's power is judged against the other classes' limits, not against the
/// soft pours of the same physics. Returns notes on stiff pours left out.
std::vector<std::string> add_hard_sphere_limits(std::vector<Group>& groups, GroupPlan& plan);

}  // namespace sgmp::compare
