#pragma once
/// @file pour_params.hpp
/// Everything that defines a LIGGGHTS pour, in SI units with 1 project length unit = 1 m.
///
/// The sphere diameter follows the project's sizing rule, d = (18 φ* / (π N))^(1/3), so
/// the N spheres hold a solid volume of 3 φ* whatever N is. A blend (`size_modes`, as
/// `sgmp pack` takes them: size_modes.hpp) has the generalised rule's diameters a_i·s and
/// its deterministic counts, so a pour and an SGMP pack of the same request hold the same
/// particles. The starting cloud fills the container's footprint from the floor up to a
/// height h at solid fraction `cloud_fraction`:
///     Σ N_i (π/6) d_i³ = cloud_fraction · (1.25 − d_max)² · (h − d_max)
/// (the box the centres of the largest spheres may take), with walls or periodic sides.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/sides.hpp"
#include "sgmp/pack/size_modes.hpp"

namespace sgmp::reference {

/// One species of a pour: its spheres' diameter (m), how many, and their density (kg/m³).
struct PourSpecies {
    double diameter = 0.0;
    std::size_t count = 0;
    double density = 0.0;
};

/// 1 project length unit in metres. Positions pass through unchanged.
inline constexpr double kMetresPerUnit = 1.0;

struct PourParams {
    std::size_t count = 0;           ///< number of spheres
    std::uint64_t seed = 1;          ///< drives LIGGGHTS' seeds and the colour labels
    double phi_target = 0.63;        ///< φ* of the sizing rule
    double friction = 0.5;           ///< sliding friction μ, particles and walls
    double restitution = 0.5;        ///< normal coefficient of restitution e
    double rolling_friction = 0.01;  ///< rolling friction μ_r (constant directional torque)
    /// Viscous damping of the tangential spring; off for exactly frictionless pours (at μ = 0
    /// it still turns the spheres).
    bool tangential_damping = true;
    double youngs_modulus = 1e9;      ///< E (Pa)
    double poisson_ratio = 0.25;      ///< ν
    double density = 2500.0;          ///< ρ (kg/m³)
    double gravity = 9.81;            ///< g (m/s²), along −Y
    double timestep_fraction = 0.15;  ///< time step as a fraction of the Rayleigh time
    double settle_threshold = 1e-6;   ///< settled when KE_trans per particle < this · m g d
    double check_time = 0.02;         ///< simulated seconds between settling checks
    double max_time = 30.0;           ///< simulated seconds allowed in all (the step cap)
    double cloud_fraction = 0.3;      ///< solid fraction of the starting cloud
    /// Sizes, as `sgmp pack --size-modes` (fractions in `fraction_basis`, densities relative
    /// to species 1's `density`); one mode of size 1 is the equal-sphere pour.
    std::vector<SizeMode> size_modes = std::vector<SizeMode>(1);
    FractionBasis fraction_basis = FractionBasis::Number;
    std::string size_distribution;  ///< the distribution as the user named it, when given
    Sides sides = Sides::Walls;     ///< periodic: x and z periodic, the floor kept
    int ranks = 1;                  ///< MPI ranks (1: run liggghts directly)
    /// LIGGGHTS processor grid "PX,PY,PZ" with PX·PY·PZ = ranks; empty: chosen from the
    /// container's shape (launcher.hpp).
    std::string processors;
    /// Name of an SGMP starting arrangement to start from instead of the cloud.
    std::optional<std::string> arrangement;
    /// Random horizontal offsets of an arrangement's spheres, as a fraction of d
    /// (start_jitter.hpp); 0 keeps the arrangement exactly.
    double start_jitter = 0.0;

    /// Throws ParameterError (the parameter's name, its value, the rule it breaks) for the
    /// first row of the pour parameter table (pour_parameters.hpp) whose rule it breaks.
    void validate() const;

    /// The number-mean diameter d = 2⟨r⟩ (the sizing rule's d for equal spheres): the unit
    /// of overlaps and of the settling measure m(d)·g·d.
    [[nodiscard]] double diameter() const;
    /// The species in order (species 1, 2, …), with the sizing rule's diameters and the
    /// deterministic counts of size_modes.hpp; one entry for equal spheres.
    [[nodiscard]] std::vector<PourSpecies> species() const;
    [[nodiscard]] bool is_blend() const { return !is_monodisperse(size_modes); }
    /// The largest species' diameter (d for equal spheres).
    [[nodiscard]] double largest_diameter() const;
    /// The container, periodic across when `sides` says so.
    [[nodiscard]] Container container() const;
    /// Top of the starting cloud (project units = m).
    [[nodiscard]] double cloud_top() const;
};

/// Prime seeds above 10000 (LIGGGHTS demands primes) derived from the pour's seed.
struct LiggghtsSeeds {
    std::uint64_t particle_template = 0;
    std::uint64_t distribution = 0;
    std::uint64_t insertion = 0;
};
LiggghtsSeeds liggghts_seeds(std::uint64_t seed);
/// The seeds of each species of a blend: species 1 has liggghts_seeds(seed), the others
/// the following draws of the same generator.
std::vector<LiggghtsSeeds> liggghts_species_seeds(std::uint64_t seed, std::size_t species);

/// Smallest prime ≥ n (trial division; n below 2^40).
std::uint64_t next_prime(std::uint64_t n);

}  // namespace sgmp::reference
