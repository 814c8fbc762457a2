#pragma once
/// @file rdf.hpp
/// Radial distribution function with exact edge correction.
///
/// Origins are the centres in the measured region, neighbours all other particles. Bins
/// are centred on multiples of the width ΔR: bin k holds centre distances in
/// [(k − ½)·ΔR, (k + ½)·ΔR) (bin 0: [0, ½·ΔR)), so the contact distance d of equal spheres —
/// which hard-sphere packs hit exactly — is a bin centre, never an edge where floating-point
/// rounding would decide the bin. With h_k the number of (origin, neighbour) pairs in bin k
/// and V_k(i) the volume of origin i's shell k inside the space S where neighbour centres
/// can lie,
///     g_k = Σ_i h_k(i) / (ρ · Σ_i V_k(i)).
/// S is the container shrunk by the mean radius at the walls and the floor, up to the
/// highest centre. Each V_k(i) is a difference of ball volumes inside S at the shell's two
/// radii (sphere_box_volume, Gauss–Legendre); origins farther than the outermost radius from every face of S
/// need no correction (full shells).
///
/// The density ρ (option gr_density) is by default the one the origins see:
///     ρ = Σ_k Σ_i h_k(i) / Σ_k Σ_i V_k(i)
/// over every bin out to the range R, so that g → 1 far from contact for any pack shape —
/// a heap or a cone as well as a flat bed — whereas N / |S| counts the empty space above a
/// sloping surface and under-counts a wall's layering. Its bias is the relative deficit of
/// neighbours inside R, −1 / (ρ V_R) + the oscillating tail beyond R: −0.2 % at R = 5·d in a
/// pack at φ ≈ 0.6 (ρ V_R ≈ 600), small against the differences judged. `gr_density =
/// space` gives ρ = N / |S|.
///
/// Distances are measured in units of the mean diameter d; for polydisperse packs g(r) is
/// a function of centre distance over d (contacts r_i + r_j ≠ d may then fall anywhere in
/// a bin; comparisons judge g only beyond contact, r ≥ 1.1·d).
///
/// The split ratio of the second shell, g(√3·d) / g(2·d), is the ratio of the mean g in the
/// windows |r − √3·d| ≤ 0.05·d and |r − 2·d| ≤ 0.05·d, each counted from the pair distances
/// themselves with its own exact edge-corrected window volume (Σ pairs / (ρ Σ V)), so it
/// depends on neither the bin width nor where the bin edges fall.
///
/// The thesis' variant (chapter 3, eq. 3.7–3.10) is kept for reproducing its figures:
/// one origin (here the particle nearest the region's centre, instead of a random one),
/// neighbours the other centres in the region, n_k / N over φ · v_shell(R) with
/// v_shell = 4π/3 [(R + ΔR/2)³ − (R − ΔR/2)³] at the bin centre R, φ the region's packing
/// fraction used as a number density (as printed there).

#include <cmath>
#include <cstdint>
#include <vector>

#include "sgmp/pack/geometry.hpp"

namespace sgmp::metrics {

/// The space of neighbour centres S described above.
Box center_space(const std::vector<Particle>& particles, const Container& container,
                 double mean_radius);

/// The literal reading (option --gr-container-space): the container up to the top of
/// the highest sphere. Centres never come closer than r to a wall, so with this space g(r)
/// settles above 1 by about |container| / |centre space|.
Box container_space(const std::vector<Particle>& particles, const Container& container);

/// Inner and outer radius of bin k of width `width` (bins centred on k·width), and the bin
/// of a distance.
inline double bin_inner(std::size_t k, double width) {
    return k == 0 ? 0.0 : (static_cast<double>(k) - 0.5) * width;
}
inline double bin_outer(std::size_t k, double width) {
    return (static_cast<double>(k) + 0.5) * width;
}
inline std::size_t bin_of(double distance, double per_width) {
    return static_cast<std::size_t>(distance * per_width + 0.5);
}
/// Number of bins reaching out to `range` (both in units of the width, range ≥ 1): the last
/// bin is centred on the range.
inline std::size_t bins_for(double range_over_width) {
    return static_cast<std::size_t>(std::llround(range_over_width)) + 1;
}

/// Adds to out[k], k < bins, the volume inside `space` of the shell of bin k (between
/// bin_inner and bin_outer) around `center`.
void add_shell_volumes(const Vec3& center, double width, std::size_t bins, const Box& space,
                       std::vector<double>& out);

/// True when every shell out to `outer` lies inside `space` (no correction needed).
bool shells_inside(const Vec3& center, double outer, const Box& space);

/// Windows of the split ratio: centres √3 and 2, half-width 0.05 (units of d).
inline constexpr double kSplitWindowHalfWidth = 0.05;
inline constexpr double kSplitLow = 1.7320508075688772;  // √3
inline constexpr double kSplitHigh = 2.0;

/// How the density of g's ideal-gas reference is estimated (see the file comment).
enum class RdfDensity { Neighbours, Space };

struct Rdf {
    double bin_width_over_d = 0.0;
    RdfDensity density_rule = RdfDensity::Neighbours;
    std::vector<double> r_over_d;  // bin centres
    std::vector<double> g;
    std::vector<std::int64_t> pairs;   // Σ_i h_k(i)
    std::vector<double> shell_volume;  // Σ_i V_k(i)
    std::int64_t origins = 0;
    std::int64_t corrected_origins = 0;  // origins whose shells needed the correction
    double density = 0.0;                // ρ used (density_rule)
    double space_density = 0.0;          // N / |S|, for information
    Box space;
    /// Split-ratio windows (low: √3·d, high: 2·d): pairs and summed shell volume.
    std::int64_t split_pairs[2] = {0, 0};
    double split_volume[2] = {0.0, 0.0};
    double split_ratio = 0.0;  // 0 when a window is empty
};

/// Fills density (by density_rule; space_density must be set), r_over_d, g and split_ratio
/// from pairs, shell_volume and the split windows.
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

}  // namespace sgmp::metrics
