#pragma once
/// @file measure.hpp
/// All metrics of one pack in one region (definitions in compare/docs/definitions.md): packing
/// fraction and its profile, overlaps, coordination at several tolerances, g(r), the split ratio,
/// Q6 and the Voronoi local packing fraction.

#include <optional>
#include <string>
#include <vector>

#include "sgmp/metrics/coordination_tolerances.hpp"
#include "sgmp/metrics/local_structure.hpp"
#include "sgmp/metrics/mixing_profile.hpp"
#include "sgmp/metrics/overlaps.hpp"
#include "sgmp/metrics/packing_fraction.hpp"
#include "sgmp/metrics/random_close_packing.hpp"
#include "sgmp/metrics/species_structure.hpp"
#include "sgmp/metrics/voronoi.hpp"
#include "sgmp/pack/pack.hpp"

namespace sgmp::metrics {

struct MeasureOptions {
    std::optional<Box> region;    // default: the control volume (times length_scale)
    double slab_thickness = 1.0;  // φ(y) slabs, units of d
    double gr_bin_width = 0.02;   // units of d
    double gr_range = 5.0;        // units of d
    bool gr_thesis = false;       // also the thesis' single-particle RDF
    bool gr_container_space =
        false;  // g(r) space: the container up to the top sphere, not the centres' space
    RdfDensity gr_density = RdfDensity::Neighbours;  // g(r)'s density estimate (rdf.hpp)
    double q6_cutoff = 1.2;                          // Q6 bonds within this·(r_i + r_j)
    double overlap_floor = 1e-9;                     // overlaps deeper than this·d are counted
    bool voronoi = true;           // Voronoi local packing fraction (its own stage)
    std::size_t worst_count = 10;  // worst overlaps listed
    unsigned threads = 0;          // worker threads (parallel.hpp: 0 is every CPU it may use)
};

/// Throws std::invalid_argument naming the option and the rule when an option is invalid.
void validate(const MeasureOptions& options);

/// φ(y) of one species of a blend: the volume of its spheres in each slab of the profile.
struct SpeciesPhiProfile {
    int species = 0;
    std::vector<double> phi;  ///< per slab of Measurement::phi_profile; Σ over species = φ(y)
};

struct Measurement {
    std::size_t count = 0;
    double mean_diameter = 0.0;
    double min_radius = 0.0;
    double max_radius = 0.0;
    bool polydisperse = false;
    Box region;
    Container container;
    /// "metadata" (the file's header), "box" (a dump's or data file's box, its spheres
    /// reaching it), the statement ("--container", "manifest FILE:LINE") or "thesis default"
    std::string container_source;
    double top = 0.0;  // highest sphere top, max(y + r)
    double phi = 0.0;
    PhiProfile phi_profile;
    OverlapStats overlaps;
    LocalStructure local;
    std::optional<VoronoiPhi> voronoi;  // absent when not asked for
    std::optional<ThesisRdf> thesis_rdf;
    std::optional<MixingProfile> mixing;      // a blend's (particles with species) only
    std::optional<SizeMoments> size_moments;  // a polydisperse pack's δ and S
    std::optional<SpeciesStructure> species;  // a blend's: partial g_IJ(r), Z_IJ(δ)
    std::vector<SpeciesPhiProfile> phi_profile_by_species;  // a blend's, increasing species
};

/// The container of a pack: its `container` metadata key, else the thesis container.
/// Throws std::invalid_argument when the key is present but malformed.
Container container_of(const Pack& pack, std::string* source = nullptr);

/// Measures `pack`. Throws std::invalid_argument for an empty pack, a region that is not
/// inside the container or holds no centre, and invalid options.
Measurement measure(const Pack& pack, const MeasureOptions& options);

/// Seconds spent in each stage of the last measure() call on this thread (for benchmarks).
struct StageTimes {
    double index = 0.0;
    double phi = 0.0;
    double phi_profile = 0.0;
    double overlaps = 0.0;
    double local = 0.0;
    double species = 0.0;
    double voronoi = 0.0;
};
const StageTimes& last_stage_times();

}  // namespace sgmp::metrics
