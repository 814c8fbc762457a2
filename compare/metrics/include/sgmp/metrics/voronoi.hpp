#pragma once
/// @file voronoi.hpp
/// Voronoi local packing fraction (voro++). Every centre of the pack gets a cell of the
/// tessellation bounded by the container: the walls x = x_min, x_max, z = z_min, z_max, the
/// floor, and a lid at the cap
///     y_cap = max_i (y_i + r_i) + d,   d = 2⟨r⟩,
/// one mean diameter above the highest sphere top. The local packing fraction of origin i is
///     φ_i = (4/3) π r_i³ / V_i,
/// the whole sphere's volume over its cell's volume, for the origins whose centres lie in
/// `region`. Equal radii use the plain Voronoi tessellation of the centres; unequal radii the
/// radical (Laguerre) one, whose face between i and j is the plane of equal power
/// |x − c_i|² − r_i² = |x − c_j|² − r_j², so a sphere keeps to its own cell when no two
/// overlap (it equals the plain one for equal radii).
///
/// Periodic sides (Container::periodic): no lateral walls; the tessellation holds the
/// particles and their images within a margin of the faces (periodic_images.hpp), and only
/// the particles are origins, so every cell is the cell of the infinite periodic pack.
///
/// Free surface: cells of spheres at the top reach the cap, so their φ_i depends on the
/// margin d. The control volume lies a few diameters below the surface of every thesis pack,
/// where no cell reaches the cap; a region that takes in top spheres measures cells cut by
/// the cap (tests/compare/voronoi_test.cpp fixes that value for a known case).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::metrics {

struct VoronoiOptions {
    std::size_t histogram_bins = 100;  ///< bins of the local φ over [0, 1]
    /// Measured cells per slab: the measured centres are cut, by increasing x, into slabs
    /// of about this many, each tessellated on its own among the centres within 3 mean
    /// diameters of it; a cell that such a neighbourhood cannot vouch for (one not every
    /// centre within twice its largest vertex distance is in) is computed again among all
    /// centres. The slabs change no cell beyond rounding; they run on the threads.
    std::size_t cells_per_slab = 50000;
    /// Keep every origin's φ_i in VoronoiPhi::local (pictures coloured by local φ).
    bool keep_local = false;
    /// Worker threads (parallel.hpp: 0 is every CPU the process may use).
    unsigned threads = 0;
};

/// φ_i over the origins of one species of a blend.
struct VoronoiSpecies {
    int species = 0;
    std::int64_t cells = 0;  ///< its origins
    double mean = 0.0;       ///< (1/n_s) Σ φ_i over them
    double sd = 0.0;         ///< population sd
    double global = 0.0;     ///< Σ (4/3)π r_i³ / Σ V_i over them
};

/// The distribution of φ_i over the origins in the region.
struct VoronoiPhi {
    std::int64_t cells = 0;      ///< origins measured (centres in the region)
    double mean = 0.0;           ///< voronoi_phi_mean: (1/n) Σ φ_i
    double sd = 0.0;             ///< voronoi_phi_sd: population sd, √((1/n) Σ (φ_i − mean)²)
    double global = 0.0;         ///< Σ (4/3)π r_i³ / Σ V_i over the same cells
    double cell_volume = 0.0;    ///< Σ V_i over the same cells
    std::int64_t cap_cells = 0;  ///< cells among them that reach the cap (0 below the surface)
    std::vector<double> histogram;  ///< density of φ_i over equal bins of [0, 1]; Σ h_k Δ = 1.
                                    ///< A φ_i ≥ 1 (spheres overlapping deeply) counts in the
                                    ///< last bin.
    std::vector<VoronoiSpecies> by_species;  ///< a blend's, by increasing species (else empty)
    /// With VoronoiOptions::keep_local: φ_i of particle i (index into the input), NaN for a
    /// centre outside the region; else empty.
    std::vector<double> local;
};

/// Local packing fractions of the centres inside `region`, from the cells of all
/// `particles` in `container` capped as above. Deterministic: the same set of particles
/// gives the same bytes in any order and for any thread count (the slabs are fixed by the
/// input, and each cell is computed in one of them). Throws std::invalid_argument for no
/// particles, a radius that is not positive and finite, a centre outside the container or not
/// finite, an empty container or region, a region holding no centre, zero histogram bins, and a
/// cell that vanishes (a radical cell swallowed by a much larger overlapping sphere).
VoronoiPhi voronoi_local_phi(const std::vector<Particle>& particles, const Container& container,
                             const Box& region, const VoronoiOptions& options = {});

}  // namespace sgmp::metrics
