#pragma once
/// @file relax_state.hpp
/// The soft pack a relaxation minimises (relax.cpp), shared with the frictional contact
/// forces (friction.hpp). Internal to the engine.
#include <cstddef>
#include <vector>

#include "sgmp/engine/neighbour_list.hpp"
#include "sgmp/pack/geometry.hpp"

namespace sgmp::engine {

struct Triple {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
};

/// The soft pack being minimised, in an internal order that keeps neighbours close in memory.
struct State {
    std::vector<Ball> spheres;
    std::vector<Triple> v;  ///< velocities
    std::vector<Triple> f;  ///< net forces
    /// m·g of each sphere, in units of the reference m·g; empty when all are 1 (one size).
    std::vector<double> weight;
    bool gravity = true;                  ///< whether the weights act
    std::vector<float> x0, y0, z0;        ///< positions when the neighbour list was built
    std::vector<std::uint32_t> particle;  ///< index in the caller's vector
    NeighbourList neighbours;
    double skin = 0.0;
    /// The container: its `periodic` flag and periods decide the pairs' nearest images.
    Container sides;

    // Frictional relaxation only (all empty otherwise). Rotations are kept in rolling
    // coordinates q = r·θ (a length), so their generalised force is torque/r = n × F_t and
    // they take the same unit inertia and time step as the translations.
    bool frictional = false;
    double tangential_ratio = 0.0;    ///< k_t/k
    double friction = 0.0;            ///< μ
    std::vector<Triple> w;            ///< rolling velocities q̇ = r·ω
    std::vector<Triple> g;            ///< generalised torques, torque/r
    std::vector<Triple> moved;        ///< displacement since the last force evaluation
    std::vector<Triple> rolled;       ///< rolling displacement since the last evaluation
    std::vector<Triple> pair_spring;  ///< tangential spring ξ per neighbour-list slot
    std::vector<Triple> wall_spring;  ///< tangential spring ξ per sphere and wall (5 each)
    NeighbourList previous;           ///< the list before the last rebuild (to carry ξ over)

    [[nodiscard]] double weight_of(std::size_t i) const { return weight.empty() ? 1.0 : weight[i]; }
};

/// Sums over the spheres after a force evaluation.
struct ForceSums {
    double power = 0.0;            ///< P = Σ F·v (+ Σ G·q̇ when frictional)
    double force_squared = 0.0;    ///< |F|² (+ |G|²) of the whole pack
    double largest_squared = 0.0;  ///< max over spheres of |Fᵢ|² (+ |Gᵢ|²)
};

}  // namespace sgmp::engine
