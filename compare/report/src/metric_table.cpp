// The metric table, its vocabulary and the summary of one pack (agreement.hpp).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sgmp/metrics/coordination_tolerances.hpp"
#include "sgmp/report/agreement.hpp"
#include "sgmp/report/species_rows.hpp"

namespace sgmp::report {

using metrics::coordination_tolerance_names;
using metrics::coordination_tolerances;
using metrics::Measurement;

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
        // 0.05, not 0.03: material alone moves it by up to 0.048 between three input
        // scripts of one class (compare/notes/material-spread-2026-12-07.md).
        {"split_ratio", "split ratio g(√3·d)/g(2·d)", "ratio", K::Scalar, 0.05, true, "split", {}},
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
        // Information: material alone moves it by 0.004, half the class gap, so it is not
        // determined by the class (compare/notes/material-spread-2026-12-07.md).
        {"q6_local_mean",
         "Q6 (local mean)",
         "dimensionless",
         K::Scalar,
         0.0025,
         false,
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

}  // namespace sgmp::report
