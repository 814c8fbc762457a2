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
    if (rule.kind == MetricKind::Curve) {
        return p.gr;
    }
    return p.p_z.at(rule.descriptor->tolerance);  // a distribution: P(Z) at its tolerance
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
    if (rule.kind == MetricKind::Curve) {
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
        sum += p->scalar(metrics::metric_with(metrics::MetricRole::OverlapDepth).name);
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
        if (rule.kind != MetricKind::Curve) {
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
    take(row, rule.kind == MetricKind::Curve
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
    if (rule.kind != MetricKind::Curve) {
        return tv_decides_with(rule, candidate, reference, alpha, candidate_n, reference_n);
    }
    auto both = candidate;
    both.insert(both.end(), reference.begin(), reference.end());
    const auto ranges = ranges_of(both);
    return l2_decides_with(judged_bins(rule, candidate, ranges),
                           judged_bins(rule, reference, ranges), reference.front()->gr_bin_width,
                           rule.margin, alpha, candidate_n, reference_n);
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
