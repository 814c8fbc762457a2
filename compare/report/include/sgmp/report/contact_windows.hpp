#pragma once
/// @file contact_windows.hpp
/// Where a pack's g(r) has contact peaks, which the g(r) test leaves out. Equal spheres
/// touch at r = d, below the judged range [1.1·d, 5·d] (agreement.hpp). A blend's pair
/// type I, J touches at σ_IJ = (D_I + D_J)/2, which may lie inside it (a 1 : 0.5 bimodal
/// blend: 0.90, 1.35 and 1.80 number-mean diameters); there, as at σ = d, soft DEM
/// contacts (overlapping by up to about 1 % of σ) and hard SGMP ones differ by
/// construction, and the contact scale is judged by each species' Z(δ) instead. A window
/// [0.98·σ_lo, 1.1·σ_hi] is left out per contact range: one per pair type of a blend with
/// species (σ_lo = σ_hi = σ_IJ), or the whole span [2·r_min, 2·r_max] for sizes without
/// species. Packs of equal spheres have none, so their verdicts are unchanged.
#include <vector>

namespace sgmp::report {

/// Contact distances over d, from σ_lo to σ_hi.
struct ContactRange {
    double lo = 0.0;
    double hi = 0.0;
};

/// One range per pair type I ≤ J of species of mean diameters `species_diameters` (over d);
/// without species, the span [smallest, largest] diameter over d when they differ; else
/// none.
std::vector<ContactRange> contact_ranges(const std::vector<double>& species_diameters,
                                         double smallest, double largest);

/// Whether the bin [r_lo, r_hi] (over d) meets no window [0.98·lo, 1.1·hi] of `ranges`.
bool outside_contact_windows(double r_lo, double r_hi, const std::vector<ContactRange>& ranges);

}  // namespace sgmp::report
