#pragma once
/// @file metric_descriptors.hpp
/// The metric table: one descriptor per metric, the only place a metric's name is spelled.
///
/// A descriptor says what a metric is (name, label, unit, the link to its definition), how
/// it is judged (test kind: scalar, curve or distribution; the declared margin; the verdict
/// rule: an equivalence test, or information only) and where it goes: its place in the
/// per-pack metrics.json, its summary.csv column, and the views that single it out (the
/// headline, the first differences named, the trend plots, the per-species rows of a
/// blend). `measure`'s JSON writer, `sgmp batch`'s summary (summary_columns.hpp), the
/// report's metric rules and pack summaries (report/agreement.hpp), the report writers and
/// the Python module all read it. Families over the coordination tolerances (Z(δ), P(Z) at
/// δ, wall contacts) are made from coordination_tolerances() in one place.
///
/// Adding a metric: its descriptor here (metric_descriptors.cpp), its kernel (a header and
/// source under compare/metrics/, its value in Measurement) and its test; ARCHITECTURE.md,
/// "Adding a metric".

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sgmp::metrics {

struct Measurement;

/// The test a metric is judged by: a scalar (Welch equivalence of means), a curve (the L2
/// distance of mean g(r)) or a distribution (the total-variation distance of mean P(Z)).
enum class MetricKind { Scalar, Curve, Distribution };

/// The physical bound a measured value is checked against (report/physical_checks.cpp).
enum class PhysicalBound {
    NonNegative,      ///< finite and ≥ 0
    PackingFraction,  ///< also < 1, and ≤ Kepler's bound for one size
    Coordination,     ///< also ≤ the kissing bound at its tolerance
};

/// A metric that one part of the code singles out by what it is, not by its name.
enum class MetricRole {
    None,
    PackingFraction,  ///< φ: beside the thesis' φ
    Stability,        ///< the Z whose value below isostatic says a pack cannot stand
    OverlapDepth,     ///< the mean pair overlap that decides which contact rows are judged
    BatchSummary,     ///< the column whose presence marks a file as a batch summary
    Mixing,           ///< a blend's mixing profile: its largest share deviation
    PairCorrelation,  ///< g(r): its distance over the margin is the headline's g(r) ratio
    LocalPacking,     ///< the Voronoi local φ's mean (also per species of a blend)
    LocalSpread,      ///< the Voronoi local φ's sd (also per species of a blend)
};

/// A metric's scalar value in a measurement (`tolerance` is MetricDescriptor::tolerance);
/// nullopt when the measurement holds none (Voronoi not asked for).
using ScalarValue = std::optional<double> (*)(const Measurement& m, std::size_t tolerance);

/// The margin of g(r)'s L2 distance on [1.1·d, 5·d] (compare/README.md "Margins").
inline constexpr double kGrMargin = 0.03;

/// Ranks place a metric in an ordered view; kUnranked leaves it out.
inline constexpr int kUnranked = -1;
/// metrics.json ranks from here on come after "region", with the detail.
inline constexpr int kJsonDetail = 100;

struct MetricDescriptor {
    std::string name{};        ///< key in metrics.json, report.csv/json and baselines
    std::string label{};       ///< people's name
    std::string unit{};        ///< e.g. "d", "contacts/particle", "ratio"
    std::string definition{};  ///< link to its definition (compare/docs/definitions.md#…)
    MetricKind kind = MetricKind::Scalar;
    double margin = 0.0;        ///< declared equivalence margin (compare/README.md "Margins")
    bool judged = true;         ///< verdict rule: the equivalence test on the margin; false: info
    std::string short_label{};  ///< column heading of the verdict matrix
    /// δ/d of a contact metric (Z(δ), P(Z) at δ); none for the others.
    std::optional<double> contact_tolerance{};
    std::size_t tolerance = 0;      ///< index into coordination_tolerances() of a family member
    ScalarValue value = nullptr;    ///< a scalar's value; nullptr for curves and distributions
    bool integer = false;           ///< a count: written as a whole number
    bool report = true;             ///< a row of every comparison (report metric_rules())
    int json_rank = kUnranked;      ///< its place among metrics.json's metric keys
    std::string summary_column{};   ///< its summary.csv column; empty: none
    bool summary_optional = false;  ///< may be empty or absent in a summary row
    int summary_rank = kUnranked;   ///< its place among summary.csv's metric columns
    int headline_rank = kUnranked;  ///< its place in the headline (crossval)
    int leading_rank = kUnranked;   ///< its place among the differences a reader weighs first
    int trend_rank = kUnranked;     ///< its place among the plots against the count
    bool per_species = false;       ///< also judged per species of a blend
    int digits = 0;                 ///< decimals where the headline tables show its value
    PhysicalBound bound = PhysicalBound::NonNegative;
    MetricRole role = MetricRole::None;
};

/// Every metric: the report's rows first, in report order (scalars, then curves and
/// distributions, then information), then the metrics.json detail.
const std::vector<MetricDescriptor>& metric_descriptors();

/// The metric named `name`; nullptr when there is none.
const MetricDescriptor* find_metric(std::string_view name);
/// The metric named `name`; throws std::logic_error when there is none.
const MetricDescriptor& metric_descriptor(std::string_view name);
/// The metric with `role`; throws std::logic_error when none has it.
const MetricDescriptor& metric_with(MetricRole role);
/// Z(δ) at coordination tolerance index `tolerance`.
const MetricDescriptor& coordination_metric(std::size_t tolerance);
/// The metrics ranked by `rank` (a MetricDescriptor rank member), in rank order.
std::vector<const MetricDescriptor*> ranked_metrics(int MetricDescriptor::*rank);
/// The names of ranked_metrics(rank).
std::vector<std::string> ranked_metric_names(int MetricDescriptor::*rank);

/// The "definitions" of metrics.json: key (a metric, a family as "z_mean_tol_X", or a
/// detail) and its text, in the order written.
const std::vector<std::pair<std::string, std::string>>& metric_definitions();

/// The per-species metric names of a blend: "species_<I>:<metric>".
std::string species_metric_name(int species, std::string_view metric);

}  // namespace sgmp::metrics
