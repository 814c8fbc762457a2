#pragma once
/// @file agreement.hpp
/// The agreement model, general over any number of labelled groups of packs.
///
/// A comparison puts a candidate group against a reference group at one particle count.
/// Every metric gets a verdict: `agree`, `differ`, `inconclusive`, or `info` (shown without
/// a verdict: it differs by construction, e.g. the overlap depth of soft DEM spheres against
/// hard SGMP spheres).
///
/// Every verdict is an equivalence test (equivalence.hpp) of the candidate against the
/// reference on the metric's declared margin m (MetricRule::margin, justified in
/// compare/README.md "Margins"), on both groups' standard errors at their own n:
///   agree        the 90 % interval of the difference lies inside ±m;
///   differ       it lies wholly outside ±m;
///   inconclusive it straddles a margin; seeds_to_decide says how many seeds would decide.
/// Scalars: Δ = mean_candidate − mean_reference (Welch). Curves: the L2 distance of the
/// mean g(r) on [1.1·d, 5·d], by an unbiased estimate of its square with variance bounds for
/// every direction of the difference; the total-variation distance ½Σ|p − q| of the mean
/// P(Z), against the noise norm of the mean difference. Nothing rewrites a verdict afterwards:
/// there is no model spread and no power rule; the power of each test is reported as its
/// minimum detectable difference `mdd` at the candidate's n.
///
/// Contact metrics (Z(δ), P(Z) at δ) count pairs with gap ≤ δ·d; a soft pack's gaps are
/// shifted by its overlaps, so two groups whose overlap depths ε̄ (the mean pair overlap
/// over d, averaged over packs) differ by more than δ/2 compare different things at δ:
/// such a row is `info` ("below overlap depth"), e.g. Z(10⁻³) of hard SGMP spheres
/// (ε̄ = 0) against DEM pours with ε̄ ≈ 10⁻³; two DEM sets with ε̄ 0.8–1.2·10⁻³ are judged.

#include <cstddef>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sgmp/metrics/measure.hpp"
#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/report/contact_windows.hpp"
#include "sgmp/report/equivalence.hpp"
#include "sgmp/report/group_sequential.hpp"

namespace sgmp::report {

enum class Verdict { Agree, Differ, Inconclusive, Info };
/// "agree", "differ", "inconclusive", "info": the one vocabulary of every output.
std::string_view to_string(Verdict verdict);
inline std::ostream& operator<<(std::ostream& out, Verdict verdict) {
    return out << to_string(verdict);
}

using metrics::MetricKind;

/// One metric of the report.
struct MetricRule {
    std::string name;   // key in the per-pack JSON, report.csv and baselines
    std::string label;  // people's name
    std::string unit;   // e.g. "d", "contacts/particle", "ratio"
    MetricKind kind = MetricKind::Scalar;
    double margin = 0.0;      // declared equivalence margin (compare/README.md "Margins")
    bool judged = true;       // false: information only, no verdict
    std::string short_label;  // column heading of the verdict matrix
    /// δ/d of a contact metric (Z(δ), P(Z) at δ); none for the others.
    std::optional<double> contact_tolerance;
    /// The metric table's row (metric_descriptors.hpp); null for a blend's per-species rows.
    const metrics::MetricDescriptor* descriptor = nullptr;
};
/// Every metric of the table that is a row of every comparison, scalars first, in report
/// order (metric_descriptors.hpp).
const std::vector<MetricRule>& metric_rules();
/// The rule named `name`; throws std::logic_error when there is none.
const MetricRule& metric_rule(const std::string& name);

/// Range of r/d over which g(r) curves are judged: beyond the contact peak, whose soft
/// (DEM, overlapping by up to ~1 % of d) and hard (SGMP, exactly d) forms differ by
/// construction; the contact scale is judged by Z(δ) and P(Z).
inline constexpr double kGrCompareFrom = 1.1;
inline constexpr double kGrCompareTo = 5.0;
/// The margin of g(r)'s L2 distance on that range (metric_descriptors.hpp).
using metrics::kGrMargin;
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
    /// A blend's per-species values by name (species_rows.hpp), e.g.
    /// "species_2:" and a metric's name (metric_descriptors.hpp: species_metric_name);
    /// empty for equal spheres.
    std::vector<std::pair<std::string, double>> species_scalars;
    /// Where its g(r) has contact peaks (contact_windows.hpp): none for equal spheres.
    std::vector<ContactRange> contact_ranges;

    /// The scalar metric `name`: a scalar rule's, else a per-species value (NaN when this
    /// pack lacks it); throws std::logic_error for any other name.
    [[nodiscard]] double scalar(const std::string& name) const;
    /// False for a pack known only by its scalar metrics (a batch summary row,
    /// precomputed.hpp); a scalar it lacks is NaN. Metrics a pack lacks are not judged.
    [[nodiscard]] bool has_curves() const { return !gr.empty(); }
};
PackSummary summarise(const std::string& source, const Pack& pack, const metrics::Measurement& m);

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
    /// Scalars: 2·s_ref; curves: D_rep, the mean distance between pairs of reference packs
    /// (descriptive: the seed-to-seed scatter).
    double seed_spread = 0.0;
    /// Always 0: kept as a column; no model spread enters a verdict (the header).
    double model_spread = 0.0;
    /// The declared margin m (the same number as `margin`; the older column name).
    double tolerance = 0.0;
    /// "margin"; "below overlap depth" for an `info` contact row; "not measured".
    std::string tolerance_rule;
    std::optional<double> ratio;  // |Δ| / m or D / m
    /// Whether `agree` is reachable at these n: the interval's half-width is below m.
    bool power = true;
    double margin = 0.0;
    /// The 90 % interval of Δ (scalars) or of the true distance D* ≥ 0 (curves).
    double ci_low = 0.0;
    double ci_high = 0.0;
    /// Minimum detectable difference: the true |Δ| (or D*) called `differ` with
    /// probability 80 % at these n.
    double mdd = 0.0;
    double p_agree = 1.0;   // TOST p-value of H0 |Δ| ≥ m
    double p_differ = 1.0;  // p-value of H0 |Δ| ≤ m (Holm in the stand-in rule)
    std::optional<std::size_t> seeds_to_decide;  // for an inconclusive row
    Verdict verdict = Verdict::Inconclusive;
    /// Group-sequential rows (sequential_rows.hpp): the look that gave the verdict (1-based;
    /// 0 for a fixed-sample row), the looks planned, the candidate seeds it saw, the α its
    /// tests had spent by then (cumulative, each side) and the nominal level of that look.
    std::size_t look = 0;
    std::size_t looks = 0;
    std::size_t candidate_n = 0;
    double alpha_spent = kTestAlpha;
    double nominal_alpha = kTestAlpha;
    /// An undecided sequential row: the side whose seeds would decide it ("candidate":
    /// seeds_to_decide SGMP seeds in all, the reference as it is; "reference":
    /// pours_to_decide reference pours, the candidate at its last look), or "" when neither
    /// side alone would up to 10⁴.
    std::string limited_by;
    std::optional<std::size_t> pours_to_decide;
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
    std::vector<MetricRow> rows;  // in metric_rules() order
    /// Set when a pack claims an equilibrium it does not have (uncertified_reason): every
    /// row is then info, with this reason, and no verdict is given.
    std::string invalid;
    GroupCurves candidate_curves;
    GroupCurves reference_curves;

    [[nodiscard]] const MetricRow& row(const std::string& name) const;
    [[nodiscard]] std::size_t count_of(Verdict verdict) const;
};

/// Which groups to compare.
struct ReportPlan {
    std::vector<std::pair<std::size_t, std::size_t>> comparisons;  // (candidate, reference)
    /// Sets of reference groups that are classes of one kind (the DEM classes): each pair
    /// of a set is compared class against class (Report::class_comparisons), to report
    /// which classes form one family. Never used to change a verdict.
    std::vector<std::vector<std::size_t>> class_sets;
    /// Candidate seeds added in blocks (group_sequential.hpp): the planned comparisons are
    /// judged look by look on the first n packs of the candidate group in manifest order;
    /// none: one look at every pack (class comparisons are always so).
    std::optional<SequentialDesign> sequential;
};

struct Report {
    std::vector<Group> groups;
    std::vector<Comparison> comparisons;
    /// Every pair (i < j) of every class set at every common count, i as candidate.
    std::vector<Comparison> class_comparisons;
    std::vector<std::string> notes;  // e.g. counts present on one side only
    ReportPlan plan;
};

/// Compares every planned (candidate, reference) pair at every particle count present in
/// both, and the classes of every class set with each other. Throws std::invalid_argument
/// when the plan names a missing group, when packs of one count use different g(r) bins,
/// or when a pack holds a physically impossible value (check_physical).
Report build_report(std::vector<Group> groups, ReportPlan plan);

/// The judgement of one metric at one count, candidate packs against reference packs, by
/// the rules above, each one-sided test at level `alpha` (a group-sequential look passes
/// its own, sequential_rows.hpp).
MetricRow judge(const MetricRule& rule, const std::vector<const PackSummary*>& candidate,
                const std::vector<const PackSummary*>& reference, double alpha = kTestAlpha);

/// Whether the test of `rule` at one-sided level `alpha` would decide (agree or differ) with
/// `candidate_n` candidate and `reference_n` reference packs, each group scattering as it
/// does now and the estimate unchanged (P(Z): the noise scaled as one shared σ² would be).
/// sequential_rows.hpp asks it of more seeds or more pours.
bool decides_with(const MetricRule& rule, const std::vector<const PackSummary*>& candidate,
                  const std::vector<const PackSummary*>& reference, double alpha,
                  std::size_t candidate_n, std::size_t reference_n);

/// Why a pack may not be judged, or "" when it may: a relaxed pack (provenance `relax`
/// frictionless or frictional) claims a mechanical equilibrium and is judged only with
/// `certified=true` (the engine's equilibrium certificate); packs that claim none (the
/// thesis' protocol, DEM pours) are judged as they are.
std::string uncertified_reason(const PackSummary& pack);

/// Throws std::invalid_argument, naming the pack, the value and the rule, when a summary
/// holds a value outside its physical range: a scalar that is not finite, φ outside
/// [0, 0.74048] (Kepler's bound for one size; [0, 1) for packs of several sizes), Z or an
/// overlap count below 0, g(r) < 0, P(Z) outside [0, 1] or not summing to 1 ± 10⁻⁶.
void check_physical(const PackSummary& pack);

/// Distance between two curves of a metric (curve rules only): the L2 distance of g(r) on
/// [1.1·d, 5·d], or the total-variation distance ½ Σ |p − q| of P(Z).
double curve_distance(const MetricRule& rule, const PackSummary& a, const PackSummary& b);

}  // namespace sgmp::report
