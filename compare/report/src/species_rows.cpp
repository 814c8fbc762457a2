#include "sgmp/report/species_rows.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace sgmp::report {
namespace {

/// One per-species metric: the suffix of its name, its label, unit, margin and, for a
/// contact number, the gap tolerance.
struct SpeciesMetric {
    const char* name;
    const char* label;
    const char* unit;
    double margin;
    std::optional<double> contact_tolerance;
};

constexpr const char* kMixing = "mixing_deviation_max";

const std::vector<SpeciesMetric>& species_metrics() {
    static const std::vector<SpeciesMetric> metrics{
        {"z_mean_tol_1e-3", "Z(δ = 10⁻³)", "contacts/particle", 0.30, 1e-3},
        {"z_mean_tol_1e-2", "Z(δ = 10⁻²)", "contacts/particle", 0.30, 1e-2},
        {"voronoi_phi_mean", "Voronoi local φ, mean", "ratio", 0.010, std::nullopt},
    };
    return metrics;
}

std::string species_name(int species, const char* metric) {
    return "species_" + std::to_string(species) + ":" + metric;
}

bool held_by_all(const std::string& name, const std::vector<const PackSummary*>& packs) {
    return !packs.empty() && std::all_of(packs.begin(), packs.end(), [&](const PackSummary* p) {
        return !std::isnan(p->scalar(name));
    });
}

}  // namespace

bool is_species_metric(const std::string& name) {
    return name.rfind("species_", 0) == 0 || name == kMixing;
}

void add_species_scalars(const metrics::Measurement& m, PackSummary& s) {
    if (!m.species) {
        return;
    }
    const auto& names = metrics::coordination_tolerance_names();
    for (const auto& one : m.species->species) {
        for (std::size_t t = 0; t < names.size(); ++t) {
            const std::string metric = "z_mean_tol_" + names[t];
            s.species_scalars.emplace_back(species_name(one.species, metric.c_str()),
                                           one.z_mean.at(t));
        }
    }
    if (m.voronoi) {
        for (const auto& v : m.voronoi->by_species) {
            s.species_scalars.emplace_back(species_name(v.species, "voronoi_phi_mean"), v.mean);
        }
    }
    if (m.mixing) {
        s.species_scalars.emplace_back(kMixing, m.mixing->deviation);
    }
}

std::vector<MetricRule> species_rules(const std::vector<const PackSummary*>& a,
                                      const std::vector<const PackSummary*>& b) {
    std::vector<MetricRule> rules;
    if (a.empty() || b.empty() || a.front()->species_scalars.empty()) {
        return rules;
    }
    std::map<int, bool> species;  // every species number any candidate pack names
    for (const auto& [name, value] : a.front()->species_scalars) {
        if (name.rfind("species_", 0) == 0) {
            species[std::stoi(name.substr(8))] = true;
        }
    }
    for (const auto& [number, present] : species) {
        for (const SpeciesMetric& metric : species_metrics()) {
            const std::string name = species_name(number, metric.name);
            if (!held_by_all(name, a) || !held_by_all(name, b)) {
                continue;
            }
            const std::string label =
                std::string(metric.label) + ", species " + std::to_string(number);
            rules.push_back(MetricRule{name, label, metric.unit, MetricKind::Scalar, metric.margin,
                                       true, label, metric.contact_tolerance});
        }
    }
    if (held_by_all(kMixing, a) && held_by_all(kMixing, b)) {
        rules.push_back(MetricRule{kMixing, "mixing: largest share deviation per height quarter",
                                   "ratio", MetricKind::Scalar, 0.05, true, "mixing",
                                   std::nullopt});
    }
    return rules;
}

}  // namespace sgmp::report
