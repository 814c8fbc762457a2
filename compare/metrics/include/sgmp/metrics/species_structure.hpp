#pragma once
/// @file species_structure.hpp
/// Per-species structure of a blend: partial radial distribution functions g_IJ(r) and
/// partial coordination numbers Z_IJ(δ).
///
/// Origins of species I are its centres in the measured region; neighbours of species J are
/// every centre of species J (the origin itself left out). With h_IJ,k the number of
/// (origin of I, neighbour of J) pairs in bin k and V_k(i) the volume of origin i's shell k
/// inside the space S of neighbour centres (as for g(r), rdf.hpp),
///
///     g_IJ,k = Σ_{i∈I} h_IJ,k(i) / (ρ_J · Σ_{i∈I} V_k(i)),
///
/// with ρ_J by the same rule as g(r): the density of J the origins of I see out to the range
/// (Σ_k h_IJ,k / Σ_k Σ_i V_k(i)), or N_J / |S| (`RdfDensity::Space`). Far from contact
/// g_IJ → 1; ρ_I·g_IJ = ρ_J·g_JI, so only I ≤ J are given.
///
/// Bins: the bin rule of g(r) applied at the pair type's contact distance c_IJ = r_I + r_J
/// (when each of the two species has one radius): bin k of the pair type is centred on
/// k·ΔR + o_IJ, o_IJ = c_IJ − ΔR·round(c_IJ / ΔR) ∈ [−ΔR/2, ΔR/2], so c_IJ is a bin centre and
/// never an edge where rounding would decide the bin (o_IJ = 0 for a species of several radii).
/// Bin 0 runs from 0 to o_IJ + ΔR/2.
///
/// Z_IJ(δ) is the mean, over the origins of I, of the number of neighbours of J with surface
/// gap |cᵢ − cⱼ| − rᵢ − rⱼ ≤ δ·d; the species' own Z_I(δ) = Σ_J Z_IJ(δ) (spheres only, as Z(δ)).
///
/// Pairs are found on the comparison's neighbour search (pair_columns.hpp); every sum over
/// origins runs in a fixed order, so results do not depend on the thread count.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "sgmp/metrics/rdf.hpp"
#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::metrics {

struct SpeciesStructureOptions {
    Box region;                      ///< origins: centres inside it
    Box space;                       ///< S, where neighbour centres can lie (rdf.hpp)
    double mean_diameter = 1.0;      ///< d
    double bin_width_over_d = 0.02;  ///< ΔR / d
    std::size_t bins = 251;          ///< of every g_IJ
    RdfDensity density_rule = RdfDensity::Neighbours;
    std::vector<double> tolerances;  ///< δ of Z_IJ(δ), units of d
    /// Only the first `originals` particles are the pack's (origins, counts); the rest are
    /// periodic images (periodic_images.hpp), neighbours only.
    std::size_t originals = static_cast<std::size_t>(-1);
    unsigned threads = 0;  // worker threads (parallel.hpp: 0 is every CPU it may use)
};

/// One species.
struct SpeciesSummary {
    int species = 0;
    std::int64_t origins = 0;      ///< its centres in the region
    std::int64_t count = 0;        ///< its centres in the pack
    double diameter_over_d = 0.0;  ///< its mean diameter over d
    std::vector<double> z_mean;    ///< Z_I(δ) per tolerance
};

/// One pair type I ≤ J.
struct SpeciesPair {
    int i = 0;
    int j = 0;
    double bin_offset_over_d = 0.0;    ///< o_IJ / d
    std::vector<std::int64_t> pairs;   ///< Σ_{origins of I} h_IJ,k
    std::vector<double> shell_volume;  ///< Σ_{origins of I} V_k
    double density = 0.0;              ///< ρ_J used
    std::vector<double> g;             ///< g_IJ,k
    std::vector<double> z_ij;          ///< Z_IJ(δ): J neighbours per origin of I
    std::vector<double> z_ji;          ///< Z_JI(δ): I neighbours per origin of J
};

struct SpeciesStructure {
    std::vector<SpeciesSummary> species;  ///< increasing species number
    std::vector<SpeciesPair> pairs;       ///< (1,1), (1,2), …, (2,2), … : I ≤ J
};

/// The per-species structure of `particles`; nullopt when they carry no species or only one.
std::optional<SpeciesStructure> measure_species_structure(const std::vector<Particle>& particles,
                                                          const SpeciesStructureOptions& options);

}  // namespace sgmp::metrics
