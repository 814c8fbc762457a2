#pragma once
/// @file agreement.hpp
/// The agreement model, general over any number of labelled groups of packs.
///
/// A comparison puts a candidate group against a reference group at one particle count.
/// Every metric gets a verdict: `agree`, `differ`, `inconclusive`, or `info` (shown without
/// a verdict: it differs by construction, e.g. the overlap depth of soft DEM spheres against
/// hard SGMP spheres).
///
/// Scalar metric m: difference Δ = mean_candidate − mean_reference; tolerance
///     T = max(floor_m, 2·√(s_ref² + M²)),
/// with s_ref the sample sd (n − 1) of the reference packs and M the DEM model spread, the
/// standard deviation of the model: the root mean square, over the counts where the
/// reference's variant set (a second, independent DEM set-up of the same physics) has packs,
/// of mean_variant − mean_reference. Both sds enter at 2σ.
/// ratio = |Δ| / T; agree when ratio ≤ 1. For two groups drawn from one distribution with
/// n = 5 packs each, Δ has standard error 0.63·s, so 2·s alone is exceeded with probability
/// P(|t₈| > 3.2) ≈ 1 %: T is an equivalence margin of about a single pack's 95 % range,
/// widened by the model spread.
///
/// Curve metric (g(r) on r ∈ [1.1·d, 5·d], an L2 distance; P(Z), a total-variation
/// distance): D = distance between the two mean curves; scale
///     S = D_rep · √(1 + μ²),
/// with D_rep the mean distance between pairs of reference packs and μ the model spread as
/// a multiple of D_rep (root mean square over the variant's counts of D(variant mean,
/// reference mean) / D_rep). ratio = D / S; agree when ratio ≤ 1.
///
/// Power: where several reference groups are classes of one kind (e.g. DEM friction classes),
/// a verdict against class R at count N on metric m is `inconclusive` unless every other
/// class of R's set at N differs from R on m by the same rule (R as reference): the metric cannot
/// tell the classes apart there, so agreement with R is no evidence. With fewer than two reference
/// packs the scale is undefined and curve verdicts are `inconclusive`; scalar tolerances
/// fall back to the floor.

#include <cstddef>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sgmp/compare/measure.hpp"

namespace sgmp::compare {

enum class Verdict { Agree, Differ, Inconclusive, Info };
/// "agree", "differ", "inconclusive", "info": the one vocabulary of every output.
std::string_view to_string(Verdict verdict);
inline std::ostream& operator<<(std::ostream& out, Verdict verdict) {
    return out << to_string(verdict);
}

enum class MetricKind { Scalar, Curve };

/// One metric of the report.
struct MetricRule {
    std::string name;   // key in the per-pack JSON, report.csv and baselines
    std::string label;  // people's name
    std::string unit;   // e.g. "d", "contacts/particle", "ratio"
    MetricKind kind = MetricKind::Scalar;
    double floor = 0.0;       // smallest tolerance (scalars)
    bool judged = true;       // false: information only, no verdict
    std::string short_label;  // column heading of the verdict matrix
};
/// Every metric, scalars first, in report order.
const std::vector<MetricRule>& metric_rules();
/// The rule named `name`; throws std::logic_error when there is none.
const MetricRule& metric_rule(const std::string& name);

/// Range of r/d over which g(r) curves are judged: beyond the contact peak, whose soft
/// (DEM, overlapping by up to ~1 % of d) and hard (SGMP, exactly d) forms differ by
/// construction; the contact scale is judged by Z(δ) and P(Z).
inline constexpr double kGrCompareFrom = 1.1;
inline constexpr double kGrCompareTo = 5.0;
/// The tolerances (indices into coordination_tolerances()) whose P(Z) are plotted.
inline constexpr std::size_t kPlottedPzTolerances[] = {2, 3};
/// The tolerance (δ = 1e-2) of P(Z) when many groups share one plot.
inline constexpr std::size_t kHeadlinePzTolerance = 3;

/// The numbers of one pack the report needs.
struct PackSummary {
    std::string source;  // file path
    std::vector<std::pair<std::string, std::string>> provenance;
    std::size_t count = 0;
    double diameter = 0.0;
    std::vector<double> scalars;  // by metric name, for the scalar rules
    double gr_bin_width = 0.0;
    std::vector<double> gr_r;
    std::vector<double> gr;
    std::vector<double> z_mean;            // per coordination tolerance
    std::vector<std::vector<double>> p_z;  // per coordination tolerance
    std::vector<double> phi_y_mid;
    std::vector<double> phi_y;

    /// The scalar metric `name` (throws std::logic_error for an unknown one).
    [[nodiscard]] double scalar(const std::string& name) const;
    /// False for a pack known only by its scalar metrics (a batch summary row,
    /// precomputed.hpp); a scalar it lacks is NaN. Metrics a pack lacks are not judged.
    [[nodiscard]] bool has_curves() const { return !gr.empty(); }
};
PackSummary summarise(const std::string& source, const Pack& pack, const Measurement& m);

struct Group {
    std::string label;
    std::vector<PackSummary> packs;
};

struct MetricRow {
    std::string name;
    std::string label;
    std::string unit;
    MetricKind kind = MetricKind::Scalar;
    /// Scalars: means and sds over packs; curves: unused (0).
    double candidate_mean = 0.0;
    double candidate_sd = 0.0;
    double reference_mean = 0.0;
    double reference_sd = 0.0;
    /// Scalars: Δ = candidate − reference; curves: the distance D.
    double difference = 0.0;
    /// Scalars: 2·s_ref; curves: D_rep.
    double seed_spread = 0.0;
    /// Scalars: 2·M; curves: μ·D_rep (0 without a variant set).
    double model_spread = 0.0;
    /// Scalars: T; curves: S.
    double tolerance = 0.0;
    std::string tolerance_rule;   // "floor", "seed", "seed+model"
    std::optional<double> ratio;  // |Δ| / T or D / S
    bool power = true;            // the reference classes are told apart by this metric here
    Verdict verdict = Verdict::Inconclusive;
};

/// Mean curves of one group at one count, for plots.
struct GroupCurves {
    std::vector<double> gr_r;
    std::vector<double> gr;
    std::vector<double> gr_sd;  // sd over packs, per bin
    std::vector<double> z_mean;
    std::vector<std::vector<double>> p_z;
    std::vector<double> phi_y_mid;
    std::vector<double> phi_y;
    std::string phi_y_note;  // set when the packs' slab grids differ
};

struct Comparison {
    std::string candidate;  // group labels
    std::string reference;
    std::size_t count = 0;
    std::size_t candidate_packs = 0;
    std::size_t reference_packs = 0;
    std::size_t variant_packs = 0;  // of the reference's variant set at this count
    std::vector<MetricRow> rows;    // in metric_rules() order
    GroupCurves candidate_curves;
    GroupCurves reference_curves;

    [[nodiscard]] const MetricRow& row(const std::string& name) const;
    [[nodiscard]] std::size_t count_of(Verdict verdict) const;
};

/// Which groups to compare and how tolerances are made.
struct ReportPlan {
    std::vector<std::pair<std::size_t, std::size_t>> comparisons;  // (candidate, reference)
    /// Sets of reference groups that are classes of one kind (the DEM friction classes as
    /// poured; their hard-sphere limits): a verdict against one needs the metric to tell it
    /// from every other class of its set at that count (power). A set of one: power is not
    /// assessed.
    std::vector<std::vector<std::size_t>> class_sets;
    /// Reference group → its variant group (model spread).
    std::map<std::size_t, std::size_t> variants;
    /// Reference group derived from another's packs (its hard-sphere limit) → that group:
    /// the DEM runtime shown beside the derived group is that group's.
    std::map<std::size_t, std::size_t> derived_from;
};

struct Report {
    std::vector<Group> groups;
    std::vector<Comparison> comparisons;
    std::vector<std::string> notes;  // e.g. counts present on one side only
    ReportPlan plan;
};

/// Compares every planned (candidate, reference) pair at every particle count present in
/// both. Throws std::invalid_argument when the plan names a missing group, or when packs of
/// one count use different g(r) bins.
Report build_report(std::vector<Group> groups, ReportPlan plan);

/// The judgement of one metric at one count, candidate packs against reference packs, with
/// the given model spread (absolute for scalars, relative to D_rep for curves). Power is
/// left true; `verdict` is agree / differ / inconclusive / info by the rules above.
MetricRow judge(const MetricRule& rule, const std::vector<const PackSummary*>& candidate,
                const std::vector<const PackSummary*>& reference, double model_spread);

/// Distance between two curves of a metric (curve rules only): the L2 distance of g(r) on
/// [1.1·d, 5·d], or the total-variation distance ½ Σ |p − q| of P(Z).
double curve_distance(const MetricRule& rule, const PackSummary& a, const PackSummary& b);

}  // namespace sgmp::compare
