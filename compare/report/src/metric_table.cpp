// The report's metric rules, drawn from the metric table (metric_descriptors.hpp), its
// vocabulary and the summary of one pack (agreement.hpp).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sgmp/report/agreement.hpp"
#include "sgmp/report/species_rows.hpp"

namespace sgmp::report {

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
    static const std::vector<MetricRule> rules = [] {
        std::vector<MetricRule> r;
        for (const metrics::MetricDescriptor& d : metrics::metric_descriptors()) {
            if (d.report) {
                r.push_back({d.name, d.label, d.unit, d.kind, d.margin, d.judged, d.short_label,
                             d.contact_tolerance, &d});
            }
        }
        return r;
    }();
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
    for (const auto& rule : metric_rules()) {
        if (rule.kind != MetricKind::Scalar) {
            continue;
        }
        // A value the measurement lacks (Voronoi not asked for) reads as 0.
        const auto& d = *rule.descriptor;
        const double v = d.value(m, d.tolerance).value_or(0.0);
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
