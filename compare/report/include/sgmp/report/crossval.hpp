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
#include <string_view>
#include <utility>
#include <vector>

#include "sgmp/report/agreement.hpp"
#include "sgmp/report/dem_parameters.hpp"
#include "sgmp/report/manifest.hpp"
#include "sgmp/report/thesis_table.hpp"
#include "sgmp/report/tuning.hpp"

namespace sgmp::report {

/// Metric keys of the headline, in column order (headline_rank, metric_descriptors.hpp).
const std::vector<std::string>& headline_metrics();

/// One candidate group at one count against one reference group.
struct HeadlineVerdict {
    std::string reference;
    std::vector<MetricRow> rows;  // every metric of the comparison, metric_rules() order
    std::string invalid;          // Comparison::invalid: not judged
    std::optional<double> reference_seconds;  // mean wall seconds of the reference's packs
    std::optional<double> speedup;            // reference_seconds / candidate seconds

    [[nodiscard]] const MetricRow& row(const std::string& name) const;
};

struct HeadlineRow {
    std::string group;
    std::size_t count = 0;
    std::size_t packs = 0;
    std::optional<double> seconds;  // mean wall seconds per pack, of those timed (below)
    std::size_t timed_packs = 0;    // packs whose manifest row gives seconds (timed by the run
                                    // that wrote the manifest; reused packs give none)
    double diameter = 0.0;
    std::vector<HeadlineVerdict> against;  // in reference order
    std::optional<ThesisResult> thesis;
    std::optional<double> thesis_speedup;  // thesis runtime / seconds
    std::optional<double> start_height;    // mean `start_height` key of the packs
    /// Every pack at this count carries an equilibrium certificate (`certified=true`).
    bool certified = false;
    /// Packs at this count that carry a certificate (a `certified` key), and those certified.
    std::size_t with_certificate = 0;
    std::size_t certified_packs = 0;
    std::optional<ThesisStart> thesis_start;

    /// Candidate mean of a scalar metric (from the first comparison).
    [[nodiscard]] double value(const std::string& name) const;
};

/// The family-wise level of the stand-in rule.
inline constexpr double kFamilyAlpha = 0.05;
/// A stand-in at a count needs more than this share of the metrics judged there (agree,
/// differ or inconclusive: every judged row, not only those that happened to decide) to
/// agree: a majority.
inline constexpr double kStandInAgreeShare = 0.5;

enum class StandInDecision { StandsIn, Differs, Undecided, Invalid };
/// "stands in", "differs", "undecided", "invalid" (a pack claims an equilibrium it does
/// not have: not judged).
std::string_view to_string(StandInDecision decision);

/// Whether one group stands in for another, under a stated family-wise rule.
///
/// Over the judged rows (verdict agree, differ or inconclusive) of every count, Holm's
/// step-down procedure at family-wise level α = 5 % on the rows' p_differ (the p-value of
/// "|Δ| ≤ margin"): sorted p₍₁₎ ≤ … ≤ p₍ₘ₎, p₍ᵢ₎ is rejected while p₍ᵢ₎ ≤ α/(m − i + 1).
///   differs    some row is rejected: the difference exceeds its margin, family-wise;
///   stands in  no row is rejected, and at every count at least half the decidable rows
///              agree (decidable: `power`, an interval narrower than the margin, so agree
///              was reachable; or a differ), and at least one does;
///   undecided  otherwise (too few agree: the data cannot tell).
/// Per count the same rule over that count's rows gives `counts_standing`.
/// A single row's `differ` that Holm does not keep is counted in `differ` and named.
/// One count of a stand-in record: how many judged metrics agree there, and whether the
/// mode stands in at that count.
struct CountTally {
    std::size_t count = 0;
    std::size_t agree = 0;
    std::size_t judged = 0;
    bool standing = false;
};

/// A difference Holm's procedure keeps: metric (name and label), count, |Δ| / margin.
struct KeptDifference {
    std::string metric;
    std::string label;
    std::size_t count = 0;
    double ratio = 0.0;
};

struct StandIn {
    std::vector<CountTally> tallies;   // per count compared, in count order
    std::vector<KeptDifference> kept;  // the differences Holm keeps, in row order
    std::string candidate;
    std::string reference;
    std::size_t agree = 0;
    std::size_t differ = 0;
    std::size_t inconclusive = 0;
    std::size_t differ_familywise = 0;  // rows Holm rejects
    std::size_t counts = 0;             // counts compared
    std::size_t counts_standing = 0;    // counts where it stands in by the rule
    StandInDecision decision = StandInDecision::Undecided;
    std::string invalid;            // why, for an invalid one (the first count's reason)
    std::optional<double> speedup;  // at the largest count compared
    std::size_t speedup_count = 0;
    /// The largest difference kept by Holm (else the largest row `differ`): metric label,
    /// count and |Δ| / margin.
    std::string worst_metric;
    std::size_t worst_count = 0;
    double worst_ratio = 0.0;

    [[nodiscard]] bool stands_in() const { return decision == StandInDecision::StandsIn; }
};

/// The kept difference to name first: of the metrics a reader weighs first (packing
/// fraction, contacts, structure: leading_rank, metric_descriptors.hpp), the first that
/// differs, at its largest ratio; else the largest of any metric.
KeptDifference leading_difference(const StandIn& s);

/// The stand-in record of `rows_by_count` (per count, that count's metric rows).
StandIn stand_in_from(
    const std::vector<std::pair<std::size_t, std::vector<MetricRow>>>& rows_by_count);

/// Indices of the p-values Holm's procedure rejects at family-wise level `alpha`.
std::vector<std::size_t> holm_rejected(const std::vector<double>& p, double alpha);

/// Two classes of one class set, judged against each other over every common count.
struct ClassPair {
    std::string a;
    std::string b;
    StandIn record;  // a as candidate, b as reference
    /// One family: `a` stands in for `b` by the rule (their physics is not told apart).
    [[nodiscard]] bool one_family() const { return record.stands_in(); }
};

struct CrossValidation {
    std::vector<std::string> candidates;  // group labels in manifest order
    std::vector<std::string> references;
    std::vector<std::size_t> counts;     // every count compared, ascending
    std::vector<HeadlineRow> rows;       // by candidate group, then count
    std::vector<StandIn> stand_ins;      // by reference, then candidate (best first)
    std::vector<ClassPair> class_pairs;  // the reference classes against each other
    std::vector<TunedParameter> tuning;  // disclosed on every page (tuning.hpp)
    DemParameterTable dem_parameters;    // of the reference classes (dem_parameters.hpp)

    /// Whether a tuning line names `group`.
    [[nodiscard]] bool tuned(const std::string& group) const;
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

/// The groups of a manifest and what to compare: every candidate against every reference.
/// References are the classes, one class set. A `variant` or `stiff` group (`group`
/// naming a reference) is a reference class of its own, labelled "<group> (variant)" or
/// "<group> (stiff)": another protocol or stiffness of that reference, never a tolerance.
struct GroupPlan {
    std::vector<std::string> labels;
    std::vector<std::vector<std::string>> paths;  // per label
    ReportPlan plan;
    std::vector<std::size_t> candidates;  // group indices
};
GroupPlan plan_groups(const std::vector<ManifestEntry>& manifest);

}  // namespace sgmp::report
