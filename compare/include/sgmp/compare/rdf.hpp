#pragma once
/// @file rdf.hpp
/// Radial distribution function with exact edge correction.
///
/// Origins are the centres in the measured region, neighbours all other particles. With
/// h_k the number of (origin, neighbour) pairs at centre distance in [k·ΔR, (k+1)·ΔR)
/// and V_k(i) the volume of origin i's shell k inside the space S where neighbour centres
/// can lie,
///     g_k = Σ_i h_k(i) / (ρ · Σ_i V_k(i)),   ρ = N / |S|.
/// S is the container shrunk by the mean radius at the walls and the floor, up to the
/// highest centre (the pack's top surface as seen by centres). Each V_k(i) is a
/// difference of ball volumes inside S at the shell's two radii (ball_box_volume); origins farther
/// than the outermost radius from every face of S need no correction (full shells). Distances are
/// measured in units of the mean diameter d; for polydisperse packs g(r) is a function of
/// centre distance over d.
///
/// The thesis' variant (chapter 3, eq. 3.7–3.10) is kept for reproducing its figures:
/// one origin (here the particle nearest the region's centre, instead of a random one),
/// neighbours the other centres in the region, n_k / N over φ · v_shell(R) with
/// v_shell = 4π/3 [(R + ΔR/2)³ − (R − ΔR/2)³] at the bin centre R, φ the region's packing
/// fraction used as a number density (as printed there).

#include <cstdint>
#include <vector>

#include "sgmp/pack/geometry.hpp"

namespace sgmp::compare {

/// The space of neighbour centres S described above.
Box centre_space(const std::vector<Particle>& particles, const Container& container,
                 double mean_radius);

/// The literal reading (option --gr-container-space): the container up to the top of
/// the highest sphere. Centres never come closer than r to a wall, so with this space g(r)
/// settles above 1 by about |container| / |centre space|.
Box container_space(const std::vector<Particle>& particles, const Container& container);

/// Adds to out[k], k < bins, the volume inside `space` of the shell between radii
/// k·width and (k+1)·width around `center`.
void add_shell_volumes(const Vec3& center, double width, std::size_t bins, const Box& space,
                       std::vector<double>& out);

/// True when every shell out to `outer` lies inside `space` (no correction needed).
bool shells_inside(const Vec3& center, double outer, const Box& space);

struct Rdf {
    double bin_width_over_d = 0.0;
    std::vector<double> r_over_d;  // bin centres
    std::vector<double> g;
    std::vector<std::int64_t> pairs;   // Σ_i h_k(i)
    std::vector<double> shell_volume;  // Σ_i V_k(i)
    std::int64_t origins = 0;
    std::int64_t corrected_origins = 0;  // origins whose shells needed the correction
    double density = 0.0;                // ρ = N / |S|
    Box space;
};

/// Fills r_over_d and g from pairs, shell_volume and density.
void normalise(Rdf& rdf);

struct ThesisRdf {
    std::int64_t origin_id = -1;
    std::int64_t region_count = 0;  // N of eq. 3.9
    double phi = 0.0;               // ρ of eq. 3.8
    std::vector<double> g;
};

/// The thesis' single-particle RDF over `bins` bins of `width` (absolute lengths).
ThesisRdf thesis_rdf(const std::vector<Particle>& particles, const Box& region, double phi,
                     double width, std::size_t bins);

}  // namespace sgmp::compare
