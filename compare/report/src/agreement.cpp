#include "sgmp/report/agreement.hpp"
#include "sgmp/report/species_rows.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

#include "sgmp/metrics/coordination_tolerances.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/report/equivalence.hpp"
#include "sgmp/report/group_curves.hpp"
#include "sgmp/report/sequential_rows.hpp"
#include "sgmp/report/statistics.hpp"

namespace sgmp::report {

using metrics::coordination_tolerance_names;
using metrics::coordination_tolerances;
using metrics::Measurement;
namespace {

/// A contact metric at δ is judged where the groups' overlap depths differ by at most this
/// share of δ (the header).
constexpr double kContactShiftShare = 0.5;

std::vector<const PackSummary*> packs_of(const Group& g, std::size_t count) {
    std::vector<const PackSummary*> result;
    for (const auto& p : g.packs) {
        if (p.count == count) {
            result.push_back(&p);
        }
    }
    return result;
}

std::set<std::size_t> counts_of(const Group& g) {
    std::set<std::size_t> counts;
    for (const auto& p : g.packs) {
        counts.insert(p.count);
    }
    return counts;
}

void check_same_bins(const std::vector<const PackSummary*>& packs) {
    const PackSummary* first = nullptr;
    for (const auto* p : packs) {
        if (p->has_curves()) {
            first = first != nullptr ? first : p;
        }
    }
    for (const auto* p : packs) {
        if (!p->has_curves()) {
            continue;
        }
        if (p->gr.size() != first->gr.size() || p->gr_bin_width != first->gr_bin_width) {
            throw std::invalid_argument("packs with " + std::to_string(p->count) +
                                        " particles use different g(r) bins (" + p->source +
                                        " vs " + first->source + ")");
        }
    }
}

/// The curve a rule judges, as the values of one pack.
std::vector<double> curve_values(const MetricRule& rule, const PackSummary& p) {
    if (rule.name == "g_r") {
        return p.gr;
    }
    const auto& names = coordination_tolerance_names();
    const auto it = std::find(names.begin(), names.end(), rule.name.substr(8));  // after "p_z_tol_"
    return p.p_z.at(static_cast<std::size_t>(it - names.begin()));
}

std::vector<double> mean_values(const MetricRule& rule,
                                const std::vector<const PackSummary*>& packs) {
    std::vector<std::vector<double>> curves;
    std::size_t longest = 0;
    for (const auto* p : packs) {
        curves.push_back(curve_values(rule, *p));
        longest = std::max(longest, curves.back().size());
    }
    for (auto& c : curves) {
        c.resize(longest, 0.0);  // P(Z) of different widths
    }
    return mean_curve(curves);
}

/// The contact ranges of every pack of a comparison (contact_windows.hpp).
std::vector<ContactRange> ranges_of(const std::vector<const PackSummary*>& packs) {
    std::vector<ContactRange> ranges;
    for (const auto* p : packs) {
        ranges.insert(ranges.end(), p->contact_ranges.begin(), p->contact_ranges.end());
    }
    return ranges;
}

/// Whether g(r)'s bin k is judged: r in [1.1·d, 5·d] and outside every contact window.
bool judged_bin(const PackSummary& axis, std::size_t k, const std::vector<ContactRange>& ranges) {
    const double r = axis.gr_r[k];
    const double half = 0.5 * axis.gr_bin_width;
    return r >= kGrCompareFrom && r <= kGrCompareTo &&
           outside_contact_windows(r - half, r + half, ranges);
}

double distance_between(const MetricRule& rule, const PackSummary& axis, std::vector<double> a,
                        std::vector<double> b, const std::vector<ContactRange>& ranges) {
    if (rule.name == "g_r") {
        if (a.size() != axis.gr_r.size() || b.size() != axis.gr_r.size()) {
            throw std::invalid_argument("curves to compare have different lengths");
        }
        double sum = 0.0;
        for (std::size_t k = 0; k < a.size(); ++k) {
            if (judged_bin(axis, k, ranges)) {
                sum += (a[k] - b[k]) * (a[k] - b[k]) * axis.gr_bin_width;
            }
        }
        return std::sqrt(sum);
    }
    const std::size_t n = std::max(a.size(), b.size());
    a.resize(n, 0.0);
    b.resize(n, 0.0);
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        sum += std::abs(a[k] - b[k]);
    }
    return 0.5 * sum;
}

double mean_replicate_distance(const MetricRule& rule, const std::vector<const PackSummary*>& packs,
                               const std::vector<ContactRange>& ranges) {
    double sum = 0.0;
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < packs.size(); ++i) {
        for (std::size_t j = i + 1; j < packs.size(); ++j) {
            sum += distance_between(rule, *packs[i], curve_values(rule, *packs[i]),
                                    curve_values(rule, *packs[j]), ranges);
            ++pairs;
        }
    }
    return pairs > 0 ? sum / static_cast<double>(pairs) : 0.0;
}

std::vector<double> scalar_column(const MetricRule& rule,
                                  const std::vector<const PackSummary*>& packs) {
    std::vector<double> values;
    for (const auto* p : packs) {
        values.push_back(p->scalar(rule.name));
    }
    return values;
}

/// The group's overlap depth: the mean over its packs of the mean pair overlap over d, the
/// typical compression of a contact (NaN when a pack lacks it).
double overlap_depth(const std::vector<const PackSummary*>& packs) {
    double sum = 0.0;
    for (const auto* p : packs) {
        sum += p->scalar("overlap_mean_over_d");
    }
    return packs.empty() ? 0.0 : sum / static_cast<double>(packs.size());
}

/// Copies the test's numbers into the row and sets its verdict.
void take(MetricRow& row, const EquivalenceResult& r) {
    row.margin = r.margin;
    row.tolerance = r.margin;
    row.tolerance_rule = "margin";
    row.ci_low = r.ci_low;
    row.ci_high = r.ci_high;
    row.mdd = r.mdd;
    row.p_agree = r.p_agree;
    row.p_differ = r.p_differ;
    row.seeds_to_decide = r.seeds_to_decide;
    row.power = r.zero_bound < r.margin || r.decision == Decision::Agree;
    if (r.margin > 0.0) {
        row.ratio = std::abs(r.estimate) / r.margin;
    }
    switch (r.decision) {
        case Decision::Agree:
            row.verdict = Verdict::Agree;
            break;
        case Decision::Differ:
            row.verdict = Verdict::Differ;
            break;
        case Decision::Inconclusive:
            row.verdict = Verdict::Inconclusive;
            break;
    }
}

MetricRow judge_scalar(const MetricRule& rule, const std::vector<const PackSummary*>& a,
                       const std::vector<const PackSummary*>& b, double alpha) {
    MetricRow row;
    const ScalarSample sa = sample_of(scalar_column(rule, a));
    const ScalarSample sb = sample_of(scalar_column(rule, b));
    row.candidate_mean = sa.mean;
    row.candidate_sd = sa.sd;
    row.reference_mean = sb.mean;
    row.reference_sd = sb.sd;
    row.difference = sa.mean - sb.mean;
    row.seed_spread = b.size() >= 2 ? 2.0 * sb.sd : 0.0;
    const EquivalenceResult r = test_scalar(sa, sb, rule.margin, alpha);
    take(row, r);
    return row;
}

/// The curves of `packs` on the judged bins (g(r): r in [1.1·d, 5·d] outside the contact
/// windows), padded to one length.
std::vector<std::vector<double>> judged_bins(const MetricRule& rule,
                                             const std::vector<const PackSummary*>& packs,
                                             const std::vector<ContactRange>& ranges) {
    std::vector<std::vector<double>> curves;
    for (const auto* p : packs) {
        const auto values = curve_values(rule, *p);
        if (rule.name != "g_r") {
            curves.push_back(values);
            continue;
        }
        std::vector<double> kept;
        for (std::size_t k = 0; k < values.size(); ++k) {
            if (judged_bin(*p, k, ranges)) {
                kept.push_back(values[k]);
            }
        }
        curves.push_back(kept);
    }
    return curves;
}

MetricRow judge_curve(const MetricRule& rule, const std::vector<const PackSummary*>& a,
                      const std::vector<const PackSummary*>& b, double alpha) {
    MetricRow row;
    auto both = a;
    both.insert(both.end(), b.begin(), b.end());
    const std::vector<ContactRange> ranges = ranges_of(both);
    row.difference =
        distance_between(rule, *b.front(), mean_values(rule, a), mean_values(rule, b), ranges);
    row.seed_spread = b.size() >= 2 ? mean_replicate_distance(rule, b, ranges) : 0.0;
    if (b.size() < 2) {  // no reference scatter: the noise is unknown
        take(row, test_scalar({row.difference, 0.0, 1}, {0.0, 0.0, 1}, rule.margin, alpha));
        row.ci_low = 0.0;
        return row;
    }
    const auto bins_a = judged_bins(rule, a, ranges);
    const auto bins_b = judged_bins(rule, b, ranges);
    take(row, rule.name == "g_r"
                  ? test_l2_curves(bins_a, bins_b, b.front()->gr_bin_width, rule.margin, alpha)
                  : test_total_variation(row.difference, noise_variance(bins_a, bins_b),
                                         rule.margin, std::min(a.size(), b.size()), alpha));
    return row;
}

/// The total-variation test of P(Z) with n_a and n_b packs: the per-bin noise variances
/// scaled as one shared σ² would scale them, (1/n_a + 1/n_b)/(1/|a| + 1/|b|).
bool tv_decides_with(const MetricRule& rule, const std::vector<const PackSummary*>& a,
                     const std::vector<const PackSummary*>& b, double alpha, std::size_t n_a,
                     std::size_t n_b) {
    auto both = a;
    both.insert(both.end(), b.begin(), b.end());
    const auto ranges = ranges_of(both);
    const double distance =
        distance_between(rule, *b.front(), mean_values(rule, a), mean_values(rule, b), ranges);
    const auto inverse = [](std::size_t n) { return 1.0 / static_cast<double>(n); };
    const double scale = (inverse(n_a) + inverse(n_b)) / (inverse(a.size()) + inverse(b.size()));
    auto variance = noise_variance(judged_bins(rule, a, ranges), judged_bins(rule, b, ranges));
    for (double& v : variance) {
        v *= scale;
    }
    return test_total_variation(distance, variance, rule.margin, std::min(n_a, n_b), alpha)
               .decision != Decision::Inconclusive;
}

Comparison compare_at(const Group& candidate, const Group& reference, std::size_t count) {
    const auto a = packs_of(candidate, count);
    const auto b = packs_of(reference, count);
    auto all = a;
    all.insert(all.end(), b.begin(), b.end());
    check_same_bins(all);

    Comparison c;
    c.candidate = candidate.label;
    c.reference = reference.label;
    c.count = count;
    c.candidate_packs = a.size();
    c.reference_packs = b.size();
    for (const auto& rule : metric_rules()) {
        c.rows.push_back(judge(rule, a, b));
    }
    for (const auto& rule : species_rules(a, b)) {  // blends: per species, after the others
        c.rows.push_back(judge(rule, a, b));
    }
    std::size_t uncertified = 0;
    std::string reason;
    for (const auto* p : all) {
        const std::string why = uncertified_reason(*p);
        uncertified += why.empty() ? 0 : 1;
        reason = reason.empty() ? why : reason;
    }
    if (uncertified > 0) {
        c.invalid = std::to_string(uncertified) + (uncertified == 1 ? " pack" : " packs") +
                    " not certified (" + reason + ")";
        for (auto& row : c.rows) {
            if (row.verdict != Verdict::Info) {
                row.tolerance_rule =
                    "not certified (would be " + std::string(to_string(row.verdict)) + ")";
                row.verdict = Verdict::Info;
            }
        }
    }
    c.candidate_curves = curves_of(a);
    c.reference_curves = curves_of(b);
    return c;
}

/// Every pair of every class set, class against class, at every common count.
std::vector<Comparison> class_comparisons(const Report& report) {
    std::vector<Comparison> result;
    for (const auto& set : report.plan.class_sets) {
        for (std::size_t i = 0; i < set.size(); ++i) {
            for (std::size_t j = i + 1; j < set.size(); ++j) {
                const Group& a = report.groups.at(set[i]);
                const Group& b = report.groups.at(set[j]);
                const auto b_counts = counts_of(b);
                for (const std::size_t n : counts_of(a)) {
                    if (b_counts.count(n) != 0) {
                        result.push_back(compare_at(a, b, n));
                    }
                }
            }
        }
    }
    return result;
}

}  // namespace

std::string_view to_string(Verdict verdict) {
    switch (verdict) {
        case Verdict::Agree:
            return "agree";
        case Verdict::Differ:
            return "differ";
        case Verdict::Inconclusive:
            return "inconclusive";
        case Verdict::Info:
            return "info";
    }
    return "info";
}

const std::vector<MetricRule>& metric_rules() {
    using K = MetricKind;
    // Margins: compare/README.md "Margins" says why each is what it is. The last field is
    // the gap tolerance δ/d of a contact metric.
    static const std::vector<MetricRule> rules{
        {"phi", "φ (control volume)", "ratio", K::Scalar, 0.010, true, "φ", {}},
        {"z_mean_tol_1e-6", "Z(δ = 10⁻⁶)", "contacts/particle", K::Scalar, 0.30, true, "Z 10⁻⁶",
         1e-6},
        {"z_mean_tol_1e-3", "Z(δ = 10⁻³)", "contacts/particle", K::Scalar, 0.30, true, "Z 10⁻³",
         1e-3},
        {"z_mean_tol_1e-2", "Z(δ = 10⁻²)", "contacts/particle", K::Scalar, 0.30, true, "Z 10⁻²",
         1e-2},
        {"z_mean_tol_2e-2", "Z(δ = 2·10⁻²)", "contacts/particle", K::Scalar, 0.30, true, "Z 2·10⁻²",
         2e-2},
        {"z_mean_tol_5e-2", "Z(δ = 5·10⁻²)", "contacts/particle", K::Scalar, 0.30, true, "Z 5·10⁻²",
         5e-2},
        {"split_ratio", "split ratio g(√3·d)/g(2·d)", "ratio", K::Scalar, 0.03, true, "split", {}},
        {"voronoi_phi_mean",
         "Voronoi local φ, mean",
         "ratio",
         K::Scalar,
         0.010,
         true,
         "Voronoi φ",
         {}},
        {"voronoi_phi_sd",
         "Voronoi local φ, sd",
         "ratio",
         K::Scalar,
         0.002,
         true,
         "Voronoi sd",
         {}},
        {"q6_global", "Q6 (global)", "dimensionless", K::Scalar, 0.03, true, "Q6", {}},
        {"q6_local_mean",
         "Q6 (local mean)",
         "dimensionless",
         K::Scalar,
         0.0025,
         true,
         "Q6 local",
         {}},
        {"g_r", "g(r), r ≥ 1.1·d", "ratio", K::Curve, kGrMargin, true, "g(r)", {}},
        {"p_z_tol_1e-3", "P(Z) at δ = 10⁻³", "ratio", K::Curve, 0.08, true, "P(Z) 10⁻³", 1e-3},
        {"p_z_tol_1e-2", "P(Z) at δ = 10⁻²", "ratio", K::Curve, 0.08, true, "P(Z) 10⁻²", 1e-2},
        // Information: soft DEM contacts overlap by construction, hard SGMP spheres never.
        {"z_mean_tol_0", "Z(δ = 0)", "contacts/particle", K::Scalar, 0.30, false, "Z 0", {}},
        {"overlaps", "overlapping pairs", "pairs", K::Scalar, 1.0, false, "overlaps", {}},
        {"overlap_max_over_d", "deepest overlap", "d", K::Scalar, 1e-3, false, "deepest", {}},
        {"overlap_mean_over_d", "mean overlap", "d", K::Scalar, 1e-3, false, "mean overlap", {}},
        {"wall_overlaps", "wall overlaps", "particles", K::Scalar, 1.0, false, "wall overlaps", {}},
    };
    return rules;
}

const MetricRule& metric_rule(const std::string& name) {
    for (const auto& rule : metric_rules()) {
        if (rule.name == name) {
            return rule;
        }
    }
    throw std::logic_error("no metric rule named " + name);
}

double PackSummary::scalar(const std::string& name) const {
    const auto& rules = metric_rules();
    std::size_t k = 0;
    for (const auto& rule : rules) {
        if (rule.kind != MetricKind::Scalar) {
            continue;
        }
        if (rule.name == name) {
            return scalars.at(k);
        }
        ++k;
    }
    for (const auto& [key, value] : species_scalars) {
        if (key == name) {
            return value;
        }
    }
    if (is_species_metric(name)) {  // a blend's value this pack lacks: not measured
        return std::numeric_limits<double>::quiet_NaN();
    }
    throw std::logic_error("no scalar metric named " + name);
}

const MetricRow& Comparison::row(const std::string& name) const {
    for (const auto& r : rows) {
        if (r.name == name) {
            return r;
        }
    }
    throw std::logic_error("comparison lacks metric " + name);
}

std::size_t Comparison::count_of(Verdict verdict) const {
    return static_cast<std::size_t>(std::count_if(
        rows.begin(), rows.end(), [&](const MetricRow& r) { return r.verdict == verdict; }));
}

double curve_distance(const MetricRule& rule, const PackSummary& a, const PackSummary& b) {
    return distance_between(rule, a, curve_values(rule, a), curve_values(rule, b),
                            ranges_of({&a, &b}));
}

/// Whether every pack of `packs` holds `rule`'s metric (precomputed packs may not).
static bool all_measured(const MetricRule& rule, const std::vector<const PackSummary*>& packs) {
    return std::all_of(packs.begin(), packs.end(), [&](const PackSummary* p) {
        return rule.kind == MetricKind::Scalar ? !std::isnan(p->scalar(rule.name))
                                               : p->has_curves();
    });
}

MetricRow judge(const MetricRule& rule, const std::vector<const PackSummary*>& candidate,
                const std::vector<const PackSummary*>& reference, double alpha) {
    MetricRow row;
    if (!all_measured(rule, candidate) || !all_measured(rule, reference)) {
        row.tolerance_rule = "not measured";  // no interval: inconclusive
        row.margin = row.tolerance = rule.margin;
        row.power = false;
    } else {
        row = rule.kind == MetricKind::Scalar ? judge_scalar(rule, candidate, reference, alpha)
                                              : judge_curve(rule, candidate, reference, alpha);
    }
    row.name = rule.name;
    row.label = rule.label;
    row.unit = rule.unit;
    row.kind = rule.kind;
    if (!rule.judged) {
        row.verdict = Verdict::Info;
    } else if (rule.contact_tolerance) {
        const double depths = std::abs(overlap_depth(candidate) - overlap_depth(reference));
        if (std::isnan(depths)) {  // a summary without overlap depths: not judged
            row.verdict = Verdict::Info;
            row.tolerance_rule = "overlap depth not known";
        } else if (depths > kContactShiftShare * *rule.contact_tolerance) {
            row.verdict = Verdict::Info;
            row.tolerance_rule = "below overlap depth";
        }
    }
    return row;
}

bool decides_with(const MetricRule& rule, const std::vector<const PackSummary*>& candidate,
                  const std::vector<const PackSummary*>& reference, double alpha,
                  std::size_t candidate_n, std::size_t reference_n) {
    if (candidate.empty() || reference.empty() || candidate_n < 1 || reference_n < 1 ||
        !all_measured(rule, candidate) || !all_measured(rule, reference)) {
        return false;
    }
    if (rule.kind == MetricKind::Scalar) {
        ScalarSample sa = sample_of(scalar_column(rule, candidate));
        ScalarSample sb = sample_of(scalar_column(rule, reference));
        if (sa.n < 2 && sb.n < 2) {
            return false;
        }
        sa.sd = sa.n < 2 ? sb.sd : sa.sd;  // a group of one pack scatters as the other
        sb.sd = sb.n < 2 ? sa.sd : sb.sd;
        sa.n = candidate_n;
        sb.n = reference_n;
        return test_scalar(sa, sb, rule.margin, alpha).decision != Decision::Inconclusive;
    }
    if (reference.size() < 2) {
        return false;
    }
    if (rule.name != "g_r") {
        return tv_decides_with(rule, candidate, reference, alpha, candidate_n, reference_n);
    }
    auto both = candidate;
    both.insert(both.end(), reference.begin(), reference.end());
    const auto ranges = ranges_of(both);
    return l2_decides_with(judged_bins(rule, candidate, ranges),
                           judged_bins(rule, reference, ranges),
                           reference.front()->gr_bin_width, rule.margin, alpha, candidate_n,
                           reference_n);
}

PackSummary summarise(const std::string& source, const Pack& pack, const Measurement& m) {
    PackSummary s;
    s.source = source;
    s.provenance = pack.metadata.entries();
    s.count = m.count;
    s.diameter = m.mean_diameter;
    std::vector<double> species_diameters;
    if (m.species) {
        for (const auto& one : m.species->species) {
            species_diameters.push_back(one.diameter_over_d);
        }
    }
    s.contact_ranges = contact_ranges(species_diameters, 2.0 * m.min_radius / m.mean_diameter,
                                      2.0 * m.max_radius / m.mean_diameter);
    const auto& c = m.local.coordination;
    const auto& names = coordination_tolerance_names();
    for (const auto& rule : metric_rules()) {
        if (rule.kind != MetricKind::Scalar) {
            continue;
        }
        double v = 0.0;
        if (rule.name == "phi") {
            v = m.phi;
        } else if (rule.name.rfind("z_mean_tol_", 0) == 0) {
            const auto it = std::find(names.begin(), names.end(), rule.name.substr(11));
            v = c.z_mean[static_cast<std::size_t>(it - names.begin())];
        } else if (rule.name == "split_ratio") {
            v = m.local.rdf.split_ratio;
        } else if (rule.name == "voronoi_phi_mean") {
            v = m.voronoi ? m.voronoi->mean : 0.0;
        } else if (rule.name == "voronoi_phi_sd") {
            v = m.voronoi ? m.voronoi->sd : 0.0;
        } else if (rule.name == "q6_global") {
            v = m.local.bond_order.q6_global;
        } else if (rule.name == "q6_local_mean") {
            v = m.local.bond_order.q6_local_mean;
        } else if (rule.name == "overlaps") {
            v = static_cast<double>(m.overlaps.pairs.count);
        } else if (rule.name == "overlap_max_over_d") {
            v = m.overlaps.pairs.max_over_d;
        } else if (rule.name == "overlap_mean_over_d") {
            v = m.overlaps.pairs.mean_over_d;
        } else if (rule.name == "wall_overlaps") {
            v = static_cast<double>(m.overlaps.walls.count);
        }
        s.scalars.push_back(v);
    }
    add_species_scalars(m, s);
    s.gr_bin_width = m.local.rdf.bin_width_over_d;
    s.gr_r = m.local.rdf.r_over_d;
    s.gr = m.local.rdf.g;
    s.z_mean = c.z_mean;
    s.p_z = c.p_z;
    for (std::size_t k = 0; k < m.phi_profile.phi.size(); ++k) {
        s.phi_y_mid.push_back(0.5 * (m.phi_profile.y_lo[k] + m.phi_profile.y_hi[k]));
    }
    s.phi_y = m.phi_profile.phi;
    return s;
}

namespace {

/// Kepler's bound, the densest packing of equal spheres: π/√18.
constexpr double kKeplerBound = 0.74048;

bool of_several_sizes(const PackSummary& pack) {
    for (const auto& [key, value] : pack.provenance) {
        if (key == "size_modes") {
            return value.find(',') != std::string::npos;
        }
    }
    return false;
}

[[noreturn]] void impossible(const PackSummary& pack, const std::string& what,
                             const std::string& rule) {
    throw std::invalid_argument(pack.source + ": " + what + " is physically impossible (" + rule +
                                ")");
}

/// The largest mean coordination Z(δ) a pack can have, δ the gap tolerance in units of
/// the mean diameter d. One size: 12, the kissing number, for δ ≤ 2·10⁻² (a 13th neighbour
/// needs a shell out to 1.0454·d, Tammes' problem for 13 points: more than 1 + δ even with
/// overlaps of 2 % of d); beyond, the cap-area bound 2/(1 − cos θ), sin θ = 1/(2(1 + δ))
/// (16 at δ = 5·10⁻²). Several sizes: twice that, 24 at contact, a generous bound: Z counts
/// each contact twice, and at its smaller sphere a contact is one of at most 12 with
/// spheres at least as large (shrunk to its size, they still do not overlap).
double coordination_bound(double delta, bool several_sizes) {
    constexpr double kKissingNumber = 12.0;
    constexpr double kTammesShell = 0.02;  // the largest δ of the reported ones below 0.0454
    const double sin_theta = 1.0 / (2.0 * (1.0 + delta));
    const double one_size = delta <= kTammesShell
                                ? kKissingNumber
                                : std::floor(2.0 / (1.0 - std::sqrt(1.0 - sin_theta * sin_theta)));
    return several_sizes ? 2.0 * one_size : one_size;
}

/// Refuses a mean coordination `value` at tolerance index `t` outside [0, the bound].
void check_coordination(const PackSummary& pack, std::size_t t, double value) {
    const std::string what =
        "z_mean_tol_" + coordination_tolerance_names().at(t) + " = " + std::to_string(value);
    if (!std::isfinite(value) || value < 0.0) {
        impossible(pack, what, "must be finite and >= 0");
    }
    const bool several = of_several_sizes(pack);
    const double bound = coordination_bound(coordination_tolerances().at(t), several);
    if (value > bound) {
        impossible(pack, what,
                   std::string(several ? "spheres of several sizes" : "a sphere of one size") +
                       " averages at most " + format_number(bound) + " contacts at this tolerance");
    }
}

}  // namespace

std::string uncertified_reason(const PackSummary& pack) {
    std::string relax;
    std::string certified;
    std::string residual;
    for (const auto& [key, value] : pack.provenance) {
        relax = key == "relax" ? value : relax;
        certified = key == "certified" ? value : certified;
        residual = key == "certificate_residual_max" ? value : residual;
    }
    if (relax.empty() || relax == "none" || certified == "true") {
        return "";
    }
    if (certified.empty()) {
        return "relaxed without an equilibrium certificate";
    }
    if (residual.empty()) {
        return "no equilibrium certificate for --relax " + relax;
    }
    char text[64];
    std::snprintf(text, sizeof text, "largest residual %.3g m*g",
                  std::strtod(residual.c_str(), nullptr));
    return text;
}

void check_physical(const PackSummary& pack) {
    const auto& names = coordination_tolerance_names();
    for (const auto& rule : metric_rules()) {
        if (rule.kind != MetricKind::Scalar) {
            continue;
        }
        const double v = pack.scalar(rule.name);
        if (std::isnan(v)) {
            continue;  // not measured (a batch summary row): not judged
        }
        const std::string what = rule.name + " = " + std::to_string(v);
        if (!std::isfinite(v) || v < 0.0) {
            impossible(pack, what, "must be finite and >= 0");
        }
        if (rule.name.rfind("z_mean_tol_", 0) == 0) {
            const auto z = std::find(names.begin(), names.end(), rule.name.substr(11));
            if (z != names.end()) {
                check_coordination(pack, static_cast<std::size_t>(z - names.begin()), v);
            }
        }
        if (rule.name == "phi" || rule.name == "voronoi_phi_mean") {
            if (of_several_sizes(pack) ? v >= 1.0 : v > kKeplerBound) {
                impossible(
                    pack, what,
                    of_several_sizes(pack) ? "must be < 1" : "one size packs to at most 0.74048");
            }
        }
    }
    for (std::size_t t = 0; t < pack.z_mean.size() && t < names.size(); ++t) {
        check_coordination(pack, t, pack.z_mean[t]);
    }
    for (const double g : pack.gr) {
        if (!(g >= 0.0) || !std::isfinite(g)) {
            impossible(pack, "g(r) = " + std::to_string(g), "must be finite and >= 0");
        }
    }
    for (std::size_t t = 0; t < pack.p_z.size(); ++t) {
        double sum = 0.0;
        for (const double q : pack.p_z[t]) {
            if (!(q >= 0.0 && q <= 1.0)) {
                impossible(pack, "P(Z) at " + names.at(t) + " = " + std::to_string(q),
                           "must lie in [0, 1]");
            }
            sum += q;
        }
        if (!pack.p_z[t].empty() && std::abs(sum - 1.0) > 1e-6) {
            impossible(pack, "P(Z) at " + names.at(t) + " sums to " + std::to_string(sum),
                       "must sum to 1");
        }
    }
}

Report build_report(std::vector<Group> groups, ReportPlan plan) {
    Report report;
    report.groups = std::move(groups);
    report.plan = std::move(plan);
    const auto valid = [&](std::size_t g) { return g < report.groups.size(); };
    for (const auto& [ci, ri] : report.plan.comparisons) {
        if (!valid(ci) || !valid(ri)) {
            throw std::invalid_argument("comparison names a group that does not exist");
        }
    }
    for (const auto& set : report.plan.class_sets) {
        if (!std::all_of(set.begin(), set.end(), valid)) {
            throw std::invalid_argument("a class set names a group that does not exist");
        }
    }
    for (const auto& g : report.groups) {
        for (const auto& p : g.packs) {
            check_physical(p);
        }
    }
    static BoundaryCache cache;  // boundaries depend only on the design: shared by reports
    for (const auto& [ci, ri] : report.plan.comparisons) {
        const Group& cand = report.groups[ci];
        const Group& ref = report.groups[ri];
        const auto cand_counts = counts_of(cand);
        const auto ref_counts = counts_of(ref);
        for (const std::size_t n : cand_counts) {
            if (ref_counts.count(n) != 0) {
                report.comparisons.push_back(compare_at(cand, ref, n));
                if (report.plan.sequential) {  // SGMP seeds added in blocks (sequential_rows.hpp)
                    judge_sequentially(report.comparisons.back(), packs_of(cand, n),
                                       packs_of(ref, n), *report.plan.sequential, cache);
                }
            } else {
                report.notes.push_back(cand.label + " has packs of " + std::to_string(n) +
                                       " particles, " + ref.label + " has none: not compared");
            }
        }
        for (const std::size_t n : ref_counts) {
            if (cand_counts.count(n) == 0) {
                report.notes.push_back(ref.label + " has packs of " + std::to_string(n) +
                                       " particles, " + cand.label + " has none: not compared");
            }
        }
    }
    report.class_comparisons = class_comparisons(report);
    return report;
}

}  // namespace sgmp::report
