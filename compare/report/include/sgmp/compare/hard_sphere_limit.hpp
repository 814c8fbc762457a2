#pragma once
/// @file hard_sphere_limit.hpp
/// A DEM class extrapolated to hard spheres, from its pours and the same pours settled again
/// at stiffer contacts.
///
/// The contact metrics of a settled soft-sphere pour measure its contact stiffness as well as
/// its structure: compressed Hertz contacts count as contacts. An SGMP pack is made of hard
/// spheres, so the DEM class it should reproduce is the pours' limit E → ∞. Each metric X of
/// a pour at Young's modulus E moves linearly in E^(−1/3) between E = 10⁹ and 1.6·10¹⁰ Pa
/// (data/reference/README.md, "The stiff set"), so a pour at E_soft and the same pour settled
/// again at E_stiff give
///     X_hard = X_stiff + a·(X_stiff − X_soft),   a = 1 / ((E_stiff / E_soft)^(1/3) − 1)
/// (a = 0.658 for E_stiff / E_soft = 16), applied to every scalar (Z(δ = 0) included: the
/// touching contacts' limit), to g(r) bin by bin, to Z(δ) and to P(Z) value by value. The
/// overlap metrics, shown for information only, are 0: hard spheres do not overlap. φ(y),
/// which is not judged, is the stiff pour's.

#include <optional>
#include <string>
#include <vector>

#include "sgmp/compare/agreement.hpp"

namespace sgmp::compare {

/// The label of a class's hard-sphere limit: "<class> hard-sphere limit".
std::string hard_sphere_limit_label(const std::string& class_label);
/// The class whose limit `label` names, or nothing when it names no limit.
std::optional<std::string> class_of_hard_sphere_limit(const std::string& label);

/// The provenance key holding a DEM pour's Young's modulus in Pa.
inline constexpr const char* kYoungsModulusKey = "youngs_modulus_pa";

/// a = 1 / ((E_stiff / E_soft)^(1/3) − 1); throws std::invalid_argument unless
/// E_stiff > E_soft > 0.
double hard_sphere_coefficient(double youngs_soft, double youngs_stiff);

/// One pour's hard-sphere limit from the pour (`soft`) and the same pour settled again at
/// stiffer contacts (`stiff`), by the rule above, with E read from each pack's provenance
/// (kYoungsModulusKey). Throws std::invalid_argument when a modulus is missing or not stiffer,
/// the counts differ, or the g(r) bins differ.
PackSummary hard_sphere_limit(const PackSummary& soft, const PackSummary& stiff);

/// The limit of every pour of `soft` that `stiff` holds again (same count and `seed`),
/// labelled `label`. A stiff pour without its soft one is left out and named in `unpaired`
/// (one line each); soft pours never settled again are simply not in the limit.
Group hard_sphere_limit(const Group& soft, const Group& stiff, const std::string& label,
                        std::vector<std::string>& unpaired);

}  // namespace sgmp::compare
