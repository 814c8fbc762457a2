#pragma once
/// @file arrangement.hpp
/// The four starting arrangements of the thesis (chapters 5–8): where the particles are
/// before the protocol drops them. Ids are 1..N in drop order; colours come from the ten
/// colour bins (color_bins.hpp). Every starting sphere lies inside the container (walls at
/// x, z = ±0.625, floor y = −0.625); spheres of the starting arrangement may touch but
/// never overlap. Choices where the thesis is silent are stated per arrangement.
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"
#include "sgmp/pack/random.hpp"

namespace sgmp::engine {

enum class Arrangement {
    /// x = z = 0; the first sphere rests on the floor (centre y = floor + r — the thesis'
    /// literal y = −0.625 would put it half through the floor); each next centre 1.2·d
    /// higher. Drop order bottom to top.
    SingleColumn,
    /// Flat layers of n × n, n = ⌊1/d⌋, spanning the control volume's x–z extent: centres at
    /// −0.5 + (i + ½)/n. The first layer rests on the container floor (y = floor + r),
    /// layers are d apart (touching). Drop order: layer by layer from the bottom, x fastest
    /// then z.
    SmallDense,
    /// As small-dense with n = ⌊1.25/d⌋ spanning the container: centres at
    /// −0.625 + (i + ½)·1.25/n (never closer than r to a wall).
    LargeDense,
    /// Random x, z (uniform, sphere inside the walls). A placement level starts at the
    /// floor (y = floor + r). Each particle is put at the level; when it collides with one
    /// already placed it is raised to the lowest height at which it is free, and that height
    /// becomes the new level for the particles after it (thesis §3.1, §8.1). The result is
    /// a loose random cloud, denser at the bottom. Drop order = placement order.
    LooseRandom,
};

/// "single-column", "small-dense", "large-dense", "loose-random".
std::optional<Arrangement> parse_arrangement(std::string_view name);
std::string_view to_string(Arrangement arrangement);
/// The four names, comma separated (for help and error texts).
std::string_view arrangement_names();

/// Particles per side of a layer: ⌊1/d⌋ (small-dense), ⌊1.25/d⌋ (large-dense), at least
/// 1; 1 for single-column and 0 for loose-random (no grid).
int grid_columns(Arrangement arrangement, double diameter);

/// Starting positions (before packing) with colours from the ten bins; ids 1..N in drop
/// order. `diameter` > 0. Uses `rng` for the colours (and loose-random positions).
std::vector<Particle> make_arrangement(Arrangement arrangement, std::size_t count, double diameter,
                                       Random& rng);

/// The same for particles of several sizes (diameters in drop order, each in (0, 1.25)):
/// the grids use the largest diameter for their columns and layer height (each sphere rests
/// on the bottom of its layer), the single column keeps gaps of 0.2 × the mean diameter of
/// neighbours, and the loose cloud's level is that of the sphere bottoms.
std::vector<Particle> make_arrangement(Arrangement arrangement,
                                       const std::vector<double>& diameters, Random& rng);

/// Height of a set of particles above the floor: max(y + r) − floor (0 when empty). This
/// is the "height of starting pack" reported beside the thesis' Tables 6.2, 7.2 and 8.2.
double starting_height(const std::vector<Particle>& particles, const Container& container = {});

}  // namespace sgmp::engine
