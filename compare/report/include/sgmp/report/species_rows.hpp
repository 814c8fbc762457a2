#pragma once
/// @file species_rows.hpp
/// The per-species rows of a comparison of blends: each species' contact numbers Z_I(δ) at
/// δ = 10⁻³ and 10⁻² (margin 0.30 contacts per particle, as Z(δ)), its Voronoi local φ mean
/// (margin 0.010, as the whole pack's) and the mixing profile's largest deviation (margin
/// 0.05, the ±0.05 of a well-mixed blend's volume shares per height quarter), judged by the
/// same equivalence test as every scalar (agreement.hpp). A row exists only when every pack
/// of both groups holds the value, so packs of equal spheres get none.
#include <string>
#include <vector>

#include "sgmp/metrics/measure.hpp"
#include "sgmp/report/agreement.hpp"

namespace sgmp::report {

/// True for the names of the per-species rows (species_I:…, mixing_deviation_max).
bool is_species_metric(const std::string& name);

/// Adds a blend's per-species values to `summary.species_scalars` (none for one species).
void add_species_scalars(const metrics::Measurement& measurement, PackSummary& summary);

/// The per-species rules every pack of `candidate` and `reference` can be judged on, by
/// species and then metric.
std::vector<MetricRule> species_rules(const std::vector<const PackSummary*>& candidate,
                                      const std::vector<const PackSummary*>& reference);

}  // namespace sgmp::report
