#pragma once
/// @file group_curves.hpp
/// Mean curves of a group of packs at one count, for plots: g(r) with its sd per bin, Z(δ),
/// P(Z) per tolerance (shorter distributions padded with zeros) and φ(y), whose slabs are
/// averaged over the packs that reach them.

#include <vector>

#include "sgmp/report/agreement.hpp"

namespace sgmp::report {

GroupCurves curves_of(const std::vector<const PackSummary*>& packs);

}  // namespace sgmp::report
