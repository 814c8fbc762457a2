#pragma once
/// @file coordination_tolerances.hpp
/// The gap tolerances δ at which coordination Z(δ) and P(Z) are reported: two spheres i, j
/// are in contact when |x_i − x_j| − (r_i + r_j) ≤ δ·d, d the mean diameter. The names are
/// the suffixes of the JSON and CSV keys of the families of metric_descriptors.hpp.

#include <string>
#include <vector>

namespace sgmp::metrics {

/// δ in units of d: 0, 10⁻⁶, 10⁻³, 10⁻², 2·10⁻², 5·10⁻².
const std::vector<double>& coordination_tolerances();
/// The same tolerances' names, in the same order: "0", "1e-6", "1e-3", "1e-2", "2e-2", "5e-2".
const std::vector<std::string>& coordination_tolerance_names();
/// The same for people: "0", "10⁻⁶", "10⁻³", "10⁻²", "2·10⁻²", "5·10⁻²".
const std::vector<std::string>& coordination_tolerance_labels();

}  // namespace sgmp::metrics
