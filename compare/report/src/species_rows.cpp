#include "sgmp/report/species_rows.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "sgmp/metrics/metric_descriptors.hpp"

namespace sgmp::report {
namespace {

using metrics::MetricDescriptor;

/// The whole-pack metrics also judged per species (per_species, metric_descriptors.hpp).
const std::vector<const MetricDescriptor*>& species_metrics() {
    static const std::vector<const MetricDescriptor*> list = [] {
        std::vector<const MetricDescriptor*> l;
        for (const MetricDescriptor& d : metrics::metric_descriptors()) {
            if (d.per_species) {
                l.push_back(&d);
            }
        }
        return l;
    }();
    return list;
}

/// The mixing profile's largest deviation: a blend's one whole-pack species row.
const MetricDescriptor& mixing() {
    return metrics::metric_with(metrics::MetricRole::Mixing);
}

bool held_by_all(const std::string& name, const std::vector<const PackSummary*>& packs) {
    return !packs.empty() && std::all_of(packs.begin(), packs.end(), [&](const PackSummary* p) {
        return !std::isnan(p->scalar(name));
    });
}

}  // namespace

bool is_species_metric(const std::string& name) {
    return name.rfind("species_", 0) == 0 || name == mixing().name;
}

void add_species_scalars(const metrics::Measurement& m, PackSummary& s) {
    if (!m.species) {
        return;
    }
    const std::size_t tolerances = metrics::coordination_tolerances().size();
    for (const auto& one : m.species->species) {
        for (std::size_t t = 0; t < tolerances; ++t) {
            s.species_scalars.emplace_back(
                metrics::species_metric_name(one.species, metrics::coordination_metric(t).name),
                one.z_mean.at(t));
        }
    }
    if (m.voronoi) {
        const std::string& local = metrics::metric_with(metrics::MetricRole::LocalPacking).name;
        for (const auto& v : m.voronoi->by_species) {
            s.species_scalars.emplace_back(metrics::species_metric_name(v.species, local), v.mean);
        }
    }
    if (const auto deviation = mixing().value(m, 0)) {
        s.species_scalars.emplace_back(mixing().name, *deviation);
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
        for (const MetricDescriptor* metric : species_metrics()) {
            const std::string name = metrics::species_metric_name(number, metric->name);
            if (!held_by_all(name, a) || !held_by_all(name, b)) {
                continue;
            }
            const std::string label = metric->label + ", species " + std::to_string(number);
            rules.push_back(MetricRule{name, label, metric->unit, MetricKind::Scalar,
                                       metric->margin, true, label, metric->contact_tolerance});
        }
    }
    const MetricDescriptor& mix = mixing();
    if (held_by_all(mix.name, a) && held_by_all(mix.name, b)) {
        rules.push_back(MetricRule{mix.name, mix.label, mix.unit, MetricKind::Scalar, mix.margin,
                                   mix.judged, mix.short_label, std::nullopt});
    }
    return rules;
}

}  // namespace sgmp::report
