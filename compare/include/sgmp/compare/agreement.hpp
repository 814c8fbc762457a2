#pragma once
/// @file agreement.hpp
/// The agreement model, general over any number of labelled groups of packs.
///
/// A comparison puts a candidate group against a reference group at one particle count.
/// For each scalar metric: difference = mean_candidate − mean_reference, tolerance =
/// max(2·sd_reference, floor of the metric) (sd over the reference's seeds, n − 1), and the
/// verdict is "agree" when |difference| ≤ tolerance. For g(r): the L2 distance between
/// the two mean curves on [0.8·d, 5·d] over the mean L2 distance between pairs of reference
/// replicates; a ratio ≤ 1 agrees (the candidate is as close to the reference as the
/// reference is to itself). With fewer than two reference packs the tolerance is the floor
/// and the g(r) ratio is not defined ("n/a").

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sgmp/compare/measure.hpp"

namespace sgmp::compare {

/// One scalar metric of the report with its unit and tolerance floor.
struct MetricRule {
    std::string name;    // key in the per-pack JSON
    std::string unit;    // e.g. "d", "contacts/particle", "ratio"
    double floor = 0.0;  // smallest tolerance
};
const std::vector<MetricRule>& metric_rules();

/// Range of r/d over which g(r) curves are compared.
inline constexpr double kGrCompareFrom = 0.8;
inline constexpr double kGrCompareTo = 5.0;
/// Start of the range [1.1·d, 5·d] of the informative g(r) ratio that leaves out the
/// contact peak, where soft DEM contacts (overlapping by up to ~1 % of d) and hard SGMP
/// contacts (exactly d apart) fall into different bins.
inline constexpr double kGrBeyondContactFrom = 1.1;
/// The tolerances (indices into coordination_tolerances()) whose P(Z) are plotted.
inline constexpr std::size_t kPlottedPzTolerances[] = {1, 5};
/// The tolerance (δ = 1e-2) of P(Z) when many groups share one plot.
inline constexpr std::size_t kHeadlinePzTolerance = 3;

/// The numbers of one pack the report needs.
struct PackSummary {
    std::string source;  // file path
    std::vector<std::pair<std::string, std::string>> provenance;
    std::size_t count = 0;
    double diameter = 0.0;
    std::vector<double> scalars;  // in metric_rules() order
    double gr_bin_width = 0.0;
    std::vector<double> gr_r;
    std::vector<double> gr;
    std::vector<double> z_mean;            // per coordination tolerance
    std::vector<std::vector<double>> p_z;  // per coordination tolerance
    std::vector<double> phi_y_mid;
    std::vector<double> phi_y;
};
PackSummary summarise(const std::string& source, const Pack& pack, const Measurement& m);

struct Group {
    std::string label;
    std::vector<PackSummary> packs;
};

struct MetricRow {
    std::string name;
    std::string unit;
    double candidate_mean = 0.0;
    double candidate_sd = 0.0;
    double reference_mean = 0.0;
    double reference_sd = 0.0;
    double difference = 0.0;
    double tolerance = 0.0;
    std::string tolerance_rule;  // "2 sd" or "floor"
    bool agree = false;
};

/// Mean curves of one group at one count, for plots.
struct GroupCurves {
    std::vector<double> gr_r;
    std::vector<double> gr;
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
    std::vector<MetricRow> rows;
    double gr_distance = 0.0;            // √d
    double gr_replicate_distance = 0.0;  // √d; 0 when undefined
    double gr_ratio = 0.0;               // valid when gr_ratio_defined
    bool gr_ratio_defined = false;
    bool gr_agree = false;
    /// The same ratio on [1.1·d, 5·d] (informative, no verdict); absent when undefined.
    std::optional<double> gr_beyond_contact_ratio;
    GroupCurves candidate_curves;
    GroupCurves reference_curves;

    [[nodiscard]] std::size_t disagreements() const;
};

struct Report {
    std::vector<Group> groups;
    std::vector<Comparison> comparisons;
    std::vector<std::string> notes;  // e.g. counts present on one side only
};

/// Compares every (candidate, reference) pair of group indices at every particle count
/// present in both. Throws std::invalid_argument when a pair names a missing group, or
/// when packs of one count use different g(r) bins.
Report build_report(std::vector<Group> groups,
                    const std::vector<std::pair<std::size_t, std::size_t>>& comparisons);

}  // namespace sgmp::compare
