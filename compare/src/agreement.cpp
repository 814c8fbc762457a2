#include "sgmp/compare/agreement.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "sgmp/compare/statistics.hpp"

namespace sgmp::compare {
namespace {

/// L2 distance of the candidate's mean g(r) from the reference's, and the mean distance
/// between pairs of reference replicates (0 with fewer than two).
struct GrDistances {
    double distance = 0.0;
    double replicate = 0.0;
};

std::vector<const PackSummary*> packs_of(const Group& g, std::size_t count) {
    std::vector<const PackSummary*> result;
    for (const auto& p : g.packs) {
        if (p.count == count) {
            result.push_back(&p);
        }
    }
    return result;
}

std::vector<double> column(const std::vector<const PackSummary*>& packs, std::size_t metric) {
    std::vector<double> values;
    for (const auto* p : packs) {
        values.push_back(p->scalars[metric]);
    }
    return values;
}

void check_same_bins(const std::vector<const PackSummary*>& packs) {
    for (const auto* p : packs) {
        if (p->gr.size() != packs.front()->gr.size() ||
            p->gr_bin_width != packs.front()->gr_bin_width) {
            throw std::invalid_argument("packs with " + std::to_string(p->count) +
                                        " particles use different g(r) bins (" + p->source +
                                        " vs " + packs.front()->source + ")");
        }
    }
}

GroupCurves curves_of(const std::vector<const PackSummary*>& packs) {
    GroupCurves c;
    std::vector<std::vector<double>> gr;
    std::vector<std::vector<double>> z;
    for (const auto* p : packs) {
        gr.push_back(p->gr);
        z.push_back(p->z_mean);
    }
    c.gr_r = packs.front()->gr_r;
    c.gr = mean_curve(gr);
    c.z_mean = mean_curve(z);
    const std::size_t tolerances = packs.front()->p_z.size();
    for (std::size_t t = 0; t < tolerances; ++t) {
        std::size_t longest = 0;
        for (const auto* p : packs) {
            longest = std::max(longest, p->p_z[t].size());
        }
        std::vector<std::vector<double>> pz;
        for (const auto* p : packs) {
            auto padded = p->p_z[t];
            padded.resize(longest, 0.0);
            pz.push_back(std::move(padded));
        }
        c.p_z.push_back(mean_curve(pz));
    }
    // φ(y): slabs share y0 and thickness for packs of one count (the grid starts at the
    // floor); tops differ, so each slab is averaged over the packs that reach it.
    bool same_grid = true;
    std::size_t longest = 0;
    for (const auto* p : packs) {
        const auto& y = p->phi_y_mid;
        const auto& y0 = packs.front()->phi_y_mid;
        same_grid = same_grid && !y.empty() && !y0.empty() && y[0] == y0[0] &&
                    (y.size() < 2 || y0.size() < 2 || y[1] == y0[1]);
        if (y.size() > longest) {
            longest = y.size();
            c.phi_y_mid = y;
        }
    }
    if (same_grid) {
        c.phi_y.assign(longest, 0.0);
        std::vector<int> reached(longest, 0);
        for (const auto* p : packs) {
            for (std::size_t k = 0; k < p->phi_y.size(); ++k) {
                c.phi_y[k] += p->phi_y[k];
                ++reached[k];
            }
        }
        for (std::size_t k = 0; k < longest; ++k) {
            c.phi_y[k] /= reached[k];
        }
    } else {
        c.phi_y_mid = packs.front()->phi_y_mid;
        c.phi_y = packs.front()->phi_y;
        c.phi_y_note = "slab grids differ between packs; the first pack's profile is shown";
    }
    return c;
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
    const auto& rules = metric_rules();
    for (std::size_t m = 0; m < rules.size(); ++m) {
        MetricRow row;
        row.name = rules[m].name;
        row.unit = rules[m].unit;
        const auto av = column(a, m);
        const auto bv = column(b, m);
        row.candidate_mean = mean(av);
        row.candidate_sd = sample_sd(av);
        row.reference_mean = mean(bv);
        row.reference_sd = sample_sd(bv);
        row.difference = row.candidate_mean - row.reference_mean;
        const double spread = b.size() >= 2 ? 2.0 * row.reference_sd : 0.0;
        row.tolerance = std::max(spread, rules[m].floor);
        row.tolerance_rule = spread >= rules[m].floor ? "2 sd" : "floor";
        row.agree = std::abs(row.difference) <= row.tolerance;
        c.rows.push_back(row);
    }

    c.candidate_curves = curves_of(a);
    c.reference_curves = curves_of(b);
    const double width = b.front()->gr_bin_width;
    const auto& x = c.reference_curves.gr_r;
    const auto distances = [&](double from) {
        GrDistances result;
        result.distance =
            l2_distance(x, c.candidate_curves.gr, c.reference_curves.gr, width, from, kGrCompareTo);
        if (b.size() < 2) {
            return result;
        }
        double sum = 0.0;
        std::size_t pairs = 0;
        for (std::size_t i = 0; i < b.size(); ++i) {
            for (std::size_t j = i + 1; j < b.size(); ++j) {
                sum += l2_distance(x, b[i]->gr, b[j]->gr, width, from, kGrCompareTo);
                ++pairs;
            }
        }
        result.replicate = sum / static_cast<double>(pairs);
        return result;
    };
    const GrDistances whole = distances(kGrCompareFrom);
    c.gr_distance = whole.distance;
    c.gr_replicate_distance = whole.replicate;
    if (b.size() >= 2) {
        if (whole.replicate > 0.0) {
            c.gr_ratio = whole.distance / whole.replicate;
            c.gr_ratio_defined = true;
            c.gr_agree = c.gr_ratio <= 1.0;
        } else {
            // Identical reference replicates: only an identical candidate agrees.
            c.gr_ratio_defined = false;
            c.gr_agree = c.gr_distance == 0.0;
        }
        const GrDistances beyond = distances(kGrBeyondContactFrom);
        if (beyond.replicate > 0.0) {
            c.gr_beyond_contact_ratio = beyond.distance / beyond.replicate;
        }
    }
    return c;
}

}  // namespace

const std::vector<MetricRule>& metric_rules() {
    static const std::vector<MetricRule> rules{
        {"phi", "ratio", 0.005},
        {"z_mean_tol_0", "contacts/particle", 0.1},
        {"z_mean_tol_1e-6", "contacts/particle", 0.1},
        {"z_mean_tol_1e-3", "contacts/particle", 0.1},
        {"z_mean_tol_1e-2", "contacts/particle", 0.1},
        {"z_mean_tol_2e-2", "contacts/particle", 0.1},
        {"z_mean_tol_5e-2", "contacts/particle", 0.1},
        {"q6_global", "dimensionless", 0.01},
        {"q6_local_mean", "dimensionless", 0.01},
        {"overlaps", "pairs", 1.0},
        {"overlap_max_over_d", "d", 1e-3},
        {"overlap_mean_over_d", "d", 1e-3},
        {"wall_overlaps", "particles", 1.0},
    };
    return rules;
}

std::size_t Comparison::disagreements() const {
    std::size_t n = 0;
    for (const auto& row : rows) {
        n += row.agree ? 0 : 1;
    }
    return n + ((gr_ratio_defined || reference_packs >= 2) && !gr_agree ? 1 : 0);
}

PackSummary summarise(const std::string& source, const Pack& pack, const Measurement& m) {
    PackSummary s;
    s.source = source;
    s.provenance = pack.metadata.entries();
    s.count = m.count;
    s.diameter = m.mean_diameter;
    const auto& c = m.local.coordination;
    for (const auto& rule : metric_rules()) {
        double v = 0.0;
        if (rule.name == "phi") {
            v = m.phi;
        } else if (rule.name.rfind("z_mean_tol_", 0) == 0) {
            const auto& names = coordination_tolerance_names();
            const auto it = std::find(names.begin(), names.end(), rule.name.substr(11));
            v = c.z_mean[static_cast<std::size_t>(it - names.begin())];
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

Report build_report(std::vector<Group> groups,
                    const std::vector<std::pair<std::size_t, std::size_t>>& comparisons) {
    Report report;
    report.groups = std::move(groups);
    for (const auto& [ci, ri] : comparisons) {
        if (ci >= report.groups.size() || ri >= report.groups.size()) {
            throw std::invalid_argument("comparison names a group that does not exist");
        }
        const Group& cand = report.groups[ci];
        const Group& ref = report.groups[ri];
        std::set<std::size_t> cand_counts;
        std::set<std::size_t> ref_counts;
        for (const auto& p : cand.packs) {
            cand_counts.insert(p.count);
        }
        for (const auto& p : ref.packs) {
            ref_counts.insert(p.count);
        }
        for (const std::size_t n : cand_counts) {
            if (ref_counts.count(n) != 0) {
                report.comparisons.push_back(compare_at(cand, ref, n));
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
    return report;
}

}  // namespace sgmp::compare
