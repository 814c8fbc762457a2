#include "sgmp/compare/agreement.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "sgmp/compare/group_curves.hpp"
#include "sgmp/compare/statistics.hpp"

namespace sgmp::compare {
namespace {

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

double distance_between(const MetricRule& rule, const PackSummary& axis, std::vector<double> a,
                        std::vector<double> b) {
    if (rule.name == "g_r") {
        return l2_distance(axis.gr_r, a, b, axis.gr_bin_width, kGrCompareFrom, kGrCompareTo);
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

double mean_replicate_distance(const MetricRule& rule,
                               const std::vector<const PackSummary*>& packs) {
    double sum = 0.0;
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < packs.size(); ++i) {
        for (std::size_t j = i + 1; j < packs.size(); ++j) {
            sum += curve_distance(rule, *packs[i], *packs[j]);
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

void decide(MetricRow& row, const MetricRule& rule) {
    if (!rule.judged) {
        row.verdict = Verdict::Info;
    } else if (!row.ratio) {
        row.verdict = Verdict::Inconclusive;
    } else {
        row.verdict = *row.ratio <= 1.0 ? Verdict::Agree : Verdict::Differ;
    }
}

MetricRow judge_scalar(const MetricRule& rule, const std::vector<const PackSummary*>& a,
                       const std::vector<const PackSummary*>& b, double model) {
    MetricRow row;
    const auto av = scalar_column(rule, a);
    const auto bv = scalar_column(rule, b);
    row.candidate_mean = mean(av);
    row.candidate_sd = sample_sd(av);
    row.reference_mean = mean(bv);
    row.reference_sd = sample_sd(bv);
    row.difference = row.candidate_mean - row.reference_mean;
    row.seed_spread = b.size() >= 2 ? 2.0 * row.reference_sd : 0.0;
    // M is a standard deviation of the model, as sd_ref is of the seeds: both enter at 2σ.
    row.model_spread = 2.0 * model;
    const double spread = std::hypot(row.seed_spread, row.model_spread);
    row.tolerance = std::max(spread, rule.floor);
    row.tolerance_rule = spread < rule.floor ? "floor" : (model > 0.0 ? "seed+model" : "seed");
    if (row.tolerance > 0.0) {
        row.ratio = std::abs(row.difference) / row.tolerance;
    } else {
        row.ratio = row.difference == 0.0 ? 0.0 : 1e300;
    }
    return row;
}

MetricRow judge_curve(const MetricRule& rule, const std::vector<const PackSummary*>& a,
                      const std::vector<const PackSummary*>& b, double model_relative) {
    MetricRow row;
    row.difference = distance_between(rule, *b.front(), mean_values(rule, a), mean_values(rule, b));
    row.tolerance_rule = model_relative > 0.0 ? "seed+model" : "seed";
    if (b.size() >= 2) {
        row.seed_spread = mean_replicate_distance(rule, b);
        row.model_spread = model_relative * row.seed_spread;
        row.tolerance = std::hypot(row.seed_spread, row.model_spread);
        if (row.tolerance > 0.0) {
            row.ratio = row.difference / row.tolerance;
        }
    }
    return row;
}

/// Model spread of every metric for a reference group and its variant (see the header).
std::vector<double> model_spreads(const Group& reference, const Group& variant) {
    const auto& rules = metric_rules();
    std::vector<double> sum(rules.size(), 0.0);
    std::size_t counts = 0;
    const auto variant_counts = counts_of(variant);
    for (const std::size_t n : counts_of(reference)) {
        if (variant_counts.count(n) == 0) {
            continue;
        }
        const auto r = packs_of(reference, n);
        const auto v = packs_of(variant, n);
        ++counts;
        for (std::size_t m = 0; m < rules.size(); ++m) {
            const MetricRow row = judge(rules[m], v, r, 0.0);
            const double offset =
                rules[m].kind == MetricKind::Scalar
                    ? row.difference
                    : (row.seed_spread > 0.0 ? row.difference / row.seed_spread : 0.0);
            sum[m] += offset * offset;
        }
    }
    for (auto& s : sum) {
        s = counts > 0 ? std::sqrt(s / static_cast<double>(counts)) : 0.0;
    }
    return sum;
}

Comparison compare_at(const Group& candidate, const Group& reference, const Group* variant,
                      const std::vector<double>& model, std::size_t count) {
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
    c.variant_packs = variant != nullptr ? packs_of(*variant, count).size() : 0;
    const auto& rules = metric_rules();
    for (std::size_t m = 0; m < rules.size(); ++m) {
        c.rows.push_back(judge(rules[m], a, b, model.empty() ? 0.0 : model[m]));
    }
    c.candidate_curves = curves_of(a);
    c.reference_curves = curves_of(b);
    return c;
}

/// Per metric, whether every other class at `count` differs from class `self` by the rule
/// with `self` as reference (the power of the metric there; see the header).
std::vector<bool> power_of(const Report& report, const std::vector<std::size_t>& classes,
                           std::size_t self, std::size_t count, const std::vector<double>& model) {
    const auto& rules = metric_rules();
    const auto reference = packs_of(report.groups[self], count);
    std::vector<bool> told_apart(rules.size(), true);
    for (const std::size_t other : classes) {
        const auto others = packs_of(report.groups[other], count);
        if (other == self || others.empty()) {
            continue;
        }
        for (std::size_t m = 0; m < rules.size(); ++m) {
            const MetricRow row =
                judge(rules[m], others, reference, model.empty() ? 0.0 : model[m]);
            told_apart[m] = told_apart[m] && row.verdict == Verdict::Differ;
        }
    }
    return told_apart;
}

/// Marks rows inconclusive where the reference classes cannot be told apart (see header).
/// The class-against-class judgements are made once per (class, count), not per candidate.
void apply_power(Report& report, const std::vector<std::vector<double>>& model_by_group) {
    std::map<std::pair<std::size_t, std::size_t>, std::vector<bool>> power;
    for (auto& c : report.comparisons) {
        const std::vector<std::size_t>* classes = nullptr;
        std::size_t self = 0;
        for (const auto& set : report.plan.class_sets) {
            for (const std::size_t g : set) {
                if (report.groups[g].label == c.reference && set.size() >= 2) {
                    classes = &set;
                    self = g;
                }
            }
        }
        if (classes == nullptr) {
            continue;
        }
        const auto key = std::pair{self, c.count};
        auto found = power.find(key);
        if (found == power.end()) {
            found =
                power.emplace(key, power_of(report, *classes, self, c.count, model_by_group[self]))
                    .first;
        }
        for (std::size_t m = 0; m < c.rows.size(); ++m) {
            MetricRow& row = c.rows[m];
            row.power = found->second[m];
            if (!row.power && row.verdict != Verdict::Info) {
                row.verdict = Verdict::Inconclusive;
            }
        }
    }
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
    static const std::vector<MetricRule> rules{
        {"phi", "φ (control volume)", "ratio", K::Scalar, 0.005, true, "φ"},
        {"z_mean_tol_1e-6", "Z(δ = 10⁻⁶)", "contacts/particle", K::Scalar, 0.1, true, "Z 10⁻⁶"},
        {"z_mean_tol_1e-3", "Z(δ = 10⁻³)", "contacts/particle", K::Scalar, 0.1, true, "Z 10⁻³"},
        {"z_mean_tol_1e-2", "Z(δ = 10⁻²)", "contacts/particle", K::Scalar, 0.1, true, "Z 10⁻²"},
        {"z_mean_tol_2e-2", "Z(δ = 2·10⁻²)", "contacts/particle", K::Scalar, 0.1, true, "Z 2·10⁻²"},
        {"z_mean_tol_5e-2", "Z(δ = 5·10⁻²)", "contacts/particle", K::Scalar, 0.1, true, "Z 5·10⁻²"},
        {"split_ratio", "split ratio g(√3·d)/g(2·d)", "ratio", K::Scalar, 0.02, true, "split"},
        {"voronoi_phi_mean", "Voronoi local φ, mean", "ratio", K::Scalar, 0.005, true, "Voronoi φ"},
        {"voronoi_phi_sd", "Voronoi local φ, sd", "ratio", K::Scalar, 0.002, true, "Voronoi sd"},
        {"q6_global", "Q6 (global)", "dimensionless", K::Scalar, 0.01, true, "Q6"},
        {"q6_local_mean", "Q6 (local mean)", "dimensionless", K::Scalar, 0.01, true, "Q6 local"},
        {"g_r", "g(r), r ≥ 1.1·d", "ratio", K::Curve, 0.0, true, "g(r)"},
        {"p_z_tol_1e-3", "P(Z) at δ = 10⁻³", "ratio", K::Curve, 0.0, true, "P(Z) 10⁻³"},
        {"p_z_tol_1e-2", "P(Z) at δ = 10⁻²", "ratio", K::Curve, 0.0, true, "P(Z) 10⁻²"},
        // Information: soft DEM contacts overlap by construction, hard SGMP spheres never.
        {"z_mean_tol_0", "Z(δ = 0)", "contacts/particle", K::Scalar, 0.1, false, "Z 0"},
        {"overlaps", "overlapping pairs", "pairs", K::Scalar, 1.0, false, "overlaps"},
        {"overlap_max_over_d", "deepest overlap", "d", K::Scalar, 1e-3, false, "deepest"},
        {"overlap_mean_over_d", "mean overlap", "d", K::Scalar, 1e-3, false, "mean overlap"},
        {"wall_overlaps", "wall overlaps", "particles", K::Scalar, 1.0, false, "wall overlaps"},
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
    return distance_between(rule, a, curve_values(rule, a), curve_values(rule, b));
}

/// Whether every pack of `packs` holds `rule`'s metric (precomputed packs may not).
static bool all_measured(const MetricRule& rule, const std::vector<const PackSummary*>& packs) {
    return std::all_of(packs.begin(), packs.end(), [&](const PackSummary* p) {
        return rule.kind == MetricKind::Scalar ? !std::isnan(p->scalar(rule.name))
                                               : p->has_curves();
    });
}

MetricRow judge(const MetricRule& rule, const std::vector<const PackSummary*>& candidate,
                const std::vector<const PackSummary*>& reference, double model_spread) {
    MetricRow row;
    if (!all_measured(rule, candidate) || !all_measured(rule, reference)) {
        row.tolerance_rule = "not measured";  // no ratio: inconclusive
    } else {
        row = rule.kind == MetricKind::Scalar
                  ? judge_scalar(rule, candidate, reference, model_spread)
                  : judge_curve(rule, candidate, reference, model_spread);
    }
    row.name = rule.name;
    row.label = rule.label;
    row.unit = rule.unit;
    row.kind = rule.kind;
    decide(row, rule);
    return row;
}

PackSummary summarise(const std::string& source, const Pack& pack, const Measurement& m) {
    PackSummary s;
    s.source = source;
    s.provenance = pack.metadata.entries();
    s.count = m.count;
    s.diameter = m.mean_diameter;
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
    for (const auto& [ri, vi] : report.plan.variants) {
        if (!valid(ri) || !valid(vi)) {
            throw std::invalid_argument("variant names a group that does not exist");
        }
    }
    std::vector<std::vector<double>> model(report.groups.size());
    for (const auto& [ri, vi] : report.plan.variants) {
        model[ri] = model_spreads(report.groups[ri], report.groups[vi]);
    }
    for (const auto& [ci, ri] : report.plan.comparisons) {
        const Group& cand = report.groups[ci];
        const Group& ref = report.groups[ri];
        const auto variant = report.plan.variants.find(ri);
        const Group* variant_group =
            variant == report.plan.variants.end() ? nullptr : &report.groups[variant->second];
        const auto cand_counts = counts_of(cand);
        const auto ref_counts = counts_of(ref);
        for (const std::size_t n : cand_counts) {
            if (ref_counts.count(n) != 0) {
                report.comparisons.push_back(compare_at(cand, ref, variant_group, model[ri], n));
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
    apply_power(report, model);
    return report;
}

}  // namespace sgmp::compare
