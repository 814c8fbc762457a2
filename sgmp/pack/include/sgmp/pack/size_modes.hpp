#pragma once
/// @file size_modes.hpp
/// Multi-modal (polydisperse) sizes, thesis §10.2, and blends as users state them. A size
/// distribution is a list of modes, the species 1… of a blend in the order given (relative
/// diameter a_i > 0, fraction f_i ≥ 0 in a stated basis, optional density ρ_i > 0 in any
/// unit; only ratios matter). Fractions of one basis convert to number fractions n_i:
///
///     number: n_i ∝ f_i        volume: n_i ∝ f_i / a_i³        mass: n_i ∝ f_i / (ρ_i·a_i³)
///
/// normalised to Σ n_i = 1. The thesis' sizing rule generalises to
/// (N/3)·(π/6)·Σ n_i (a_i·s)³ = φ*, which fixes the scale s; mode i has diameter a_i·s. One
/// mode of relative size 1 is the monodisperse thesis case (s = d).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sgmp/pack/drop_order.hpp"
#include "sgmp/pack/name_table.hpp"
#include "sgmp/pack/random.hpp"

namespace sgmp {

struct SizeMode {
    SizeMode() = default;
    SizeMode(double diameter, double number_or_stated_fraction,
             std::optional<double> relative_density = std::nullopt)
        : relative_diameter(diameter),
          fraction(number_or_stated_fraction),
          density(relative_density) {}
    double relative_diameter = 1.0;
    double fraction = 1.0;
    std::optional<double> density;  ///< relative density, needed by the mass basis
};

/// What the fractions of a size distribution mean.
enum class FractionBasis { Number, Volume, Mass };
const NameTable<FractionBasis, 3>& fraction_bases();
std::string_view to_string(FractionBasis basis);
std::optional<FractionBasis> parse_fraction_basis(std::string_view text);

/// "1:0.7,0.5:0.3" (relative diameter : fraction [: density], comma separated); nullopt
/// when the text is not of that form or a number is not positive and finite.
std::optional<std::vector<SizeMode>> parse_size_modes(std::string_view text);
std::string size_modes_to_string(const std::vector<SizeMode>& modes);

/// A size-distribution CSV: a header row naming `diameter` and `fraction` and optionally
/// `density` (any order, no other column), then one row per species; `#` lines and blank
/// lines are skipped. Diameters in any unit (only their ratios matter: they are divided
/// by the largest). Throws InputError (source:line: reason) for an unknown or missing
/// column, a diameter or density ≤ 0 or not finite, a negative fraction, fractions all
/// zero, or no row; a species of fraction 0 is kept (it gets no particle).
/// The diameter column may name its unit, `diameter_UNIT` (UNIT one of length_units()):
/// then `largest_diameter`, when given, receives the largest diameter in it, "200 um".
std::vector<SizeMode> parse_size_distribution_csv(std::string_view text, const std::string& source,
                                                  std::string* largest_diameter = nullptr);

/// The length units a size distribution may be stated in: m, cm, mm, um, nm.
std::string_view length_units();
/// Metres in one `unit` of length_units(); nullopt for any other text.
std::optional<double> metres_per_unit(std::string_view unit);
/// A physical length "VALUE UNIT" (VALUE > 0 and finite, UNIT of length_units()), as the
/// `largest_diameter` key states it: {VALUE, UNIT}; nullopt when the text is not one.
std::optional<std::pair<double, std::string>> parse_physical_length(std::string_view text);

/// A continuous size distribution, "lognormal:MEDIAN:SIGMA[:CLASSES[:QLO:QHI]]": ln D normal
/// with median MEDIAN (any unit) and standard deviation SIGMA, its fractions in the stated
/// basis (a volume-weighted distribution with --fraction-basis volume). It is cut at the
/// quantiles QLO < QHI (default 0.01 and 0.99) and split into CLASSES (default 10, at most
/// 1000) classes of equal probability between them; class k = 0 … CLASSES − 1 is the species
/// k + 1, of the class's own median diameter
///
///     D_k = MEDIAN · exp(SIGMA · Φ⁻¹(QLO + (k + ½)·(QHI − QLO)/CLASSES)),
///
/// fraction 1/CLASSES (Φ the standard normal distribution), so species number by
/// increasing diameter; relative diameters are D_k / D_{CLASSES−1}. Throws ParameterError
/// (`size_distribution`) for a malformed text or a value out of its range.
bool is_lognormal(std::string_view text);
std::vector<SizeMode> lognormal_modes(std::string_view text);

/// The modes with number fractions (normalised to 1) from fractions in `basis`; densities
/// are kept. Throws ParameterError (`fraction_basis`) for the mass basis when a mode has no
/// density.
std::vector<SizeMode> number_fractions(const std::vector<SizeMode>& modes, FractionBasis basis);
/// True for the single mode of relative size 1.
bool is_monodisperse(const std::vector<SizeMode>& modes);

/// Σ f_i when it differs from 1 by more than 10⁻⁹ (the fractions are then normalised, and
/// the front ends say so), nullopt otherwise.
std::optional<double> unnormalised_total(const std::vector<SizeMode>& modes);

/// The scale s: (N/3)·(π/6)·Σ f_i (a_i s)³ = φ* with fractions normalised.
double diameter_scale(std::size_t count, double phi_target, const std::vector<SizeMode>& modes);

/// Particles per mode: the largest-remainder rounding of n_i·N (ties to the earlier mode),
/// so each count is within one particle of n_i·N and they sum to N.
std::vector<std::size_t> mode_counts(std::size_t count, const std::vector<SizeMode>& modes);

/// Diameters and species of the N particles in drop order.
struct DrawnSizes {
    std::vector<double> diameters;
    std::vector<int> species;  ///< mode index + 1; all 0 for a single mode
};

/// Diameters of the N particles in drop order: mode_counts of each mode, in `order`
/// (drop_order.hpp; shuffled by Fisher–Yates with `rng`, stratified without it). A
/// monodisperse list draws nothing from `rng`. `modes` hold number fractions.
DrawnSizes draw_sizes(std::size_t count, double phi_target, const std::vector<SizeMode>& modes,
                      Random& rng, DropOrder order = DropOrder::Shuffled);

/// The diameters of draw_sizes alone.
std::vector<double> draw_diameters(std::size_t count, double phi_target,
                                   const std::vector<SizeMode>& modes, Random& rng);

}  // namespace sgmp
