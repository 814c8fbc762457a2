#pragma once
/// @file particle.hpp
/// A sphere of the pack: centre, radius, a colour label and its species.

#include <Eigen/Core>
#include <cstdint>

namespace sgmp {

/// Positions and displacements. Axes as the thesis: X left-right, Y up (gravity is -Y),
/// Z front-back; lengths in units of the control volume's side.
using Vec3 = Eigen::Vector3d;

/// One sphere. `color` is a label in [0, 10) used only for visualisation (thesis 3.1).
/// `species` numbers the component of a blend, 1… in the order the size distribution
/// gives them; 0 for a pack of one species (then no file writes a species column).
struct Particle {
    std::int64_t id = 0;
    Vec3 center = Vec3::Zero();
    double radius = 0.0;
    int color = 0;
    int species = 0;
};

/// Largest species number a reader accepts.
inline constexpr int kMaxSpecies = 1000000;

/// True when some particle has a species (> 0): the writers then add a species column.
template <class Particles>
bool has_species(const Particles& particles) {
    for (const auto& p : particles) {
        if (p.species > 0) {
            return true;
        }
    }
    return false;
}

/// Signed surface gap between two spheres: |ci - cj| - ri - rj (negative when they overlap).
double surface_gap(const Particle& a, const Particle& b);

/// True when the spheres overlap: |ci - cj| < ri + rj, decided on squared distances.
bool overlaps(const Particle& a, const Particle& b);

}  // namespace sgmp
