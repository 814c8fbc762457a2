// The metric table (metric_descriptors.hpp): every metric's name, definition, test and
// places, declared once. Margins: compare/README.md "Margins" says why each is what it is.
#include "sgmp/metrics/metric_descriptors.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "sgmp/metrics/measure.hpp"

namespace sgmp::metrics {
namespace {

using D = MetricDescriptor;
using K = MetricKind;
using R = MetricRole;
using B = PhysicalBound;

constexpr std::string_view kDefinitions = "compare/docs/definitions.md#";

std::string link(std::string_view anchor) {
    return std::string(kDefinitions) + std::string(anchor);
}

/// The rank given for tolerance index t, kUnranked when none is.
int rank_at(std::size_t t, std::initializer_list<std::pair<std::size_t, int>> ranks) {
    for (const auto& [tolerance, rank] : ranks) {
        if (tolerance == t) {
            return rank;
        }
    }
    return kUnranked;
}

bool one_of(std::size_t t, std::initializer_list<std::size_t> tolerances) {
    return std::find(tolerances.begin(), tolerances.end(), t) != tolerances.end();
}

/// Z(δ) at tolerance index t: judged at every δ > 0; at δ = 0 information only (soft DEM
/// contacts overlap by construction, hard SGMP spheres never).
D coordination(std::size_t t) {
    const std::string& name = coordination_tolerance_names().at(t);
    const std::string& label = coordination_tolerance_labels().at(t);
    const bool contact = t != 0;
    return {.name = "z_mean_tol_" + name,
            .label = "Z(δ = " + label + ")",
            .unit = "contacts/particle",
            .definition = link("coordination"),
            .margin = 0.30,
            .judged = contact,
            .short_label = "Z " + label,
            .contact_tolerance =
                contact ? std::optional<double>(coordination_tolerances().at(t)) : std::nullopt,
            .tolerance = t,
            .value = [](const Measurement& m, std::size_t k) -> std::optional<double> {
                return m.local.coordination.z_mean.at(k);
            },
            .json_rank = 10 + static_cast<int>(t),
            .summary_column = "z_" + name,
            .summary_rank = 10 + static_cast<int>(t),
            .headline_rank = rank_at(t, {{2, 1}, {3, 2}}),
            .leading_rank = rank_at(t, {{2, 1}, {3, 2}}),
            .trend_rank = rank_at(t, {{2, 1}}),
            .per_species = one_of(t, {2, 3}),
            .digits = 2,
            .bound = B::Coordination,
            .role = t == 2 ? R::Stability : R::None};
}

/// P(Z) at tolerance index t, judged as a distribution.
D contact_distribution(std::size_t t) {
    const std::string& label = coordination_tolerance_labels().at(t);
    return {.name = "p_z_tol_" + coordination_tolerance_names().at(t),
            .label = "P(Z) at δ = " + label,
            .unit = "ratio",
            .definition = link("coordination"),
            .kind = K::Distribution,
            .margin = 0.08,
            .short_label = "P(Z) " + label,
            .contact_tolerance = coordination_tolerances().at(t),
            .tolerance = t,
            .headline_rank = rank_at(t, {{2, 4}})};
}

/// Wall and floor contacts at tolerance index t (metrics.json detail).
D wall_contacts(std::size_t t) {
    return {.name = "wall_contacts_tol_" + coordination_tolerance_names().at(t),
            .label = "wall contacts at δ = " + coordination_tolerance_labels().at(t),
            .unit = "contacts",
            .definition = link("coordination"),
            .judged = false,
            .tolerance = t,
            .value = [](const Measurement& m, std::size_t k) -> std::optional<double> {
                return static_cast<double>(m.local.coordination.wall_contacts.at(k));
            },
            .integer = true,
            .report = false,
            .json_rank = kJsonDetail + 10 + static_cast<int>(t)};
}

/// The report's scalars before the coordination family: none; after it, in report order.
void add_structure(std::vector<D>& t) {
    // 0.05, not 0.03: material alone moves it by up to 0.048 between three input scripts of
    // one class (compare/notes/material-spread-2026-12-07.md).
    t.push_back({.name = "split_ratio",
                 .label = "split ratio g(√3·d)/g(2·d)",
                 .unit = "ratio",
                 .definition = link("split-ratio"),
                 .margin = 0.05,
                 .short_label = "split",
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return m.local.rdf.split_ratio;
                 },
                 .json_rank = 22,
                 .summary_column = "split_ratio",
                 .summary_rank = 40,
                 .headline_rank = 3,
                 .leading_rank = 4,
                 .trend_rank = 2,
                 .digits = 3,
                 .role = R::BatchSummary});
    t.push_back({.name = "voronoi_phi_mean",
                 .label = "Voronoi local φ, mean",
                 .unit = "ratio",
                 .definition = link("voronoi-local-phi"),
                 .margin = 0.010,
                 .short_label = "Voronoi φ",
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return m.voronoi ? std::optional<double>(m.voronoi->mean) : std::nullopt;
                 },
                 .json_rank = 23,
                 .summary_column = "voronoi_phi_mean",
                 .summary_optional = true,
                 .summary_rank = 41,
                 .leading_rank = 5,
                 .per_species = true,
                 .bound = B::PackingFraction,
                 .role = R::LocalPacking});
    t.push_back({.name = "voronoi_phi_sd",
                 .label = "Voronoi local φ, sd",
                 .unit = "ratio",
                 .definition = link("voronoi-local-phi"),
                 .margin = 0.002,
                 .short_label = "Voronoi sd",
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return m.voronoi ? std::optional<double>(m.voronoi->sd) : std::nullopt;
                 },
                 .json_rank = 24,
                 .role = R::LocalSpread});
    t.push_back({.name = "q6_global",
                 .label = "Q6 (global)",
                 .unit = "dimensionless",
                 .definition = link("q6"),
                 .margin = 0.03,
                 .short_label = "Q6",
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return m.local.bond_order.q6_global;
                 },
                 .json_rank = 20});
    // Information: material alone moves it by 0.004, half the class gap, so it is not
    // determined by the class (compare/notes/material-spread-2026-12-07.md).
    t.push_back({.name = "q6_local_mean",
                 .label = "Q6 (local mean)",
                 .unit = "dimensionless",
                 .definition = link("q6"),
                 .margin = 0.0025,
                 .judged = false,
                 .short_label = "Q6 local",
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return m.local.bond_order.q6_local_mean;
                 },
                 .json_rank = 21});
    t.push_back({.name = "g_r",
                 .label = "g(r), r ≥ 1.1·d",
                 .unit = "ratio",
                 .definition = link("g-r"),
                 .kind = K::Curve,
                 .margin = kGrMargin,
                 .short_label = "g(r)",
                 .headline_rank = 5,
                 .leading_rank = 3,
                 .role = R::PairCorrelation});
}

/// Overlaps: information in the report (soft DEM spheres overlap by construction).
void add_overlaps(std::vector<D>& t) {
    t.push_back({.name = "overlaps",
                 .label = "overlapping pairs",
                 .unit = "pairs",
                 .definition = link("overlaps"),
                 .margin = 1.0,
                 .judged = false,
                 .short_label = "overlaps",
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return static_cast<double>(m.overlaps.pairs.count);
                 },
                 .integer = true,
                 .json_rank = 1,
                 .summary_column = "overlaps",
                 .summary_rank = 30});
    t.push_back({.name = "overlap_max_over_d",
                 .label = "deepest overlap",
                 .unit = "d",
                 .definition = link("overlaps"),
                 .margin = 1e-3,
                 .judged = false,
                 .short_label = "deepest",
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return m.overlaps.pairs.max_over_d;
                 },
                 .json_rank = 2,
                 .summary_column = "overlap_max",
                 .summary_rank = 31});
    // The overlap depth that decides which contact metrics are judged (a summary written
    // before it was a column reads as not measured).
    t.push_back({.name = "overlap_mean_over_d",
                 .label = "mean overlap",
                 .unit = "d",
                 .definition = link("overlaps"),
                 .margin = 1e-3,
                 .judged = false,
                 .short_label = "mean overlap",
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return m.overlaps.pairs.mean_over_d;
                 },
                 .json_rank = kJsonDetail,
                 .summary_column = "overlap_mean",
                 .summary_optional = true,
                 .summary_rank = 32,
                 .role = R::OverlapDepth});
    t.push_back({.name = "wall_overlaps",
                 .label = "wall overlaps",
                 .unit = "particles",
                 .definition = link("overlaps"),
                 .margin = 1.0,
                 .judged = false,
                 .short_label = "wall overlaps",
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return static_cast<double>(m.overlaps.walls.count);
                 },
                 .integer = true,
                 .json_rank = kJsonDetail + 2,
                 .summary_column = "wall_overlaps",
                 .summary_rank = 33});
}

/// metrics.json's detail and a blend's mixing: not rows of every comparison.
void add_detail(std::vector<D>& t) {
    t.push_back({.name = "overlaps_any",
                 .label = "overlapping pairs, any depth",
                 .unit = "pairs",
                 .definition = link("overlaps"),
                 .judged = false,
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return static_cast<double>(m.overlaps.pairs.count_any);
                 },
                 .integer = true,
                 .report = false,
                 .json_rank = kJsonDetail + 1});
    t.push_back({.name = "wall_overlap_max_over_d",
                 .label = "deepest wall overlap",
                 .unit = "d",
                 .definition = link("overlaps"),
                 .judged = false,
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return m.overlaps.walls.max_over_d;
                 },
                 .report = false,
                 .json_rank = kJsonDetail + 3});
    t.push_back({.name = "wall_overlap_mean_over_d",
                 .label = "mean wall overlap",
                 .unit = "d",
                 .definition = link("overlaps"),
                 .judged = false,
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return m.overlaps.walls.mean_over_d;
                 },
                 .report = false,
                 .json_rank = kJsonDetail + 4});
    for (std::size_t k = 0; k < coordination_tolerances().size(); ++k) {
        t.push_back(wall_contacts(k));
    }
    t.push_back({.name = "mixing_deviation_max",
                 .label = "mixing: largest share deviation per height quarter",
                 .unit = "ratio",
                 .definition = link("mixing-profile-blends"),
                 .margin = 0.05,
                 .short_label = "mixing",
                 .value = [](const Measurement& m, std::size_t) -> std::optional<double> {
                     return m.mixing ? std::optional<double>(m.mixing->deviation) : std::nullopt;
                 },
                 .report = false,
                 .role = R::Mixing});
}

/// Refuses a table in which two metrics share a name or a rank of one view.
void check_table(const std::vector<D>& table) {
    for (int D::*rank :
         {&D::json_rank, &D::summary_rank, &D::headline_rank, &D::leading_rank, &D::trend_rank}) {
        std::map<int, std::string> seen;
        for (const D& d : table) {
            if (d.*rank != kUnranked && !seen.emplace(d.*rank, d.name).second) {
                throw std::logic_error("metrics " + seen[d.*rank] + " and " + d.name +
                                       " share a rank");
            }
        }
    }
    std::map<std::string, int> names;
    for (const D& d : table) {
        if (names[d.name]++ > 0) {
            throw std::logic_error("two metrics are named " + d.name);
        }
    }
}

std::vector<D> make_table() {
    std::vector<D> t;
    t.push_back(
        {.name = "phi",
         .label = "φ (control volume)",
         .unit = "ratio",
         .definition = link("phi"),
         .margin = 0.010,
         .short_label = "φ",
         .value = [](const Measurement& m, std::size_t) -> std::optional<double> { return m.phi; },
         .json_rank = 0,
         .summary_column = "phi",
         .summary_rank = 0,
         .headline_rank = 0,
         .leading_rank = 0,
         .trend_rank = 0,
         .digits = 4,
         .bound = B::PackingFraction,
         .role = R::PackingFraction});
    const std::size_t tolerances = coordination_tolerances().size();
    for (std::size_t k = 1; k < tolerances; ++k) {
        t.push_back(coordination(k));
    }
    add_structure(t);
    for (std::size_t k = 0; k < tolerances; ++k) {
        if (one_of(k, {2, 3})) {  // P(Z) judged at δ = 10⁻³ and 10⁻²
            t.push_back(contact_distribution(k));
        }
    }
    t.push_back(coordination(0));
    add_overlaps(t);
    add_detail(t);
    check_table(t);
    return t;
}

}  // namespace

const std::vector<MetricDescriptor>& metric_descriptors() {
    static const std::vector<MetricDescriptor> table = make_table();
    return table;
}

const MetricDescriptor* find_metric(std::string_view name) {
    for (const MetricDescriptor& d : metric_descriptors()) {
        if (d.name == name) {
            return &d;
        }
    }
    return nullptr;
}

const MetricDescriptor& metric_descriptor(std::string_view name) {
    if (const MetricDescriptor* d = find_metric(name)) {
        return *d;
    }
    throw std::logic_error("no metric named " + std::string(name));
}

const MetricDescriptor& metric_with(MetricRole role) {
    for (const MetricDescriptor& d : metric_descriptors()) {
        if (d.role == role) {
            return d;
        }
    }
    throw std::logic_error("no metric has the role asked for");
}

const MetricDescriptor& coordination_metric(std::size_t tolerance) {
    for (const MetricDescriptor& d : metric_descriptors()) {
        if (d.bound == PhysicalBound::Coordination && d.tolerance == tolerance) {
            return d;
        }
    }
    throw std::logic_error("no coordination metric at tolerance index " +
                           std::to_string(tolerance));
}

std::vector<const MetricDescriptor*> ranked_metrics(int MetricDescriptor::*rank) {
    std::vector<const MetricDescriptor*> ranked;
    for (const MetricDescriptor& d : metric_descriptors()) {
        if (d.*rank != kUnranked) {
            ranked.push_back(&d);
        }
    }
    std::sort(
        ranked.begin(), ranked.end(),
        [&](const MetricDescriptor* a, const MetricDescriptor* b) { return a->*rank < b->*rank; });
    return ranked;
}

std::vector<std::string> ranked_metric_names(int MetricDescriptor::*rank) {
    std::vector<std::string> names;
    for (const MetricDescriptor* d : ranked_metrics(rank)) {
        names.push_back(d->name);
    }
    return names;
}

std::string species_metric_name(int species, std::string_view metric) {
    return "species_" + std::to_string(species) + ":" + std::string(metric);
}

}  // namespace sgmp::metrics
