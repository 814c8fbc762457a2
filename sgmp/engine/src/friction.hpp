#pragma once
/// @file friction.hpp
/// Coulomb-limited tangential contacts of the frictional relaxation (`--relax frictional`),
/// after Cundall and Strack (Géotechnique 29, 47, 1979).
///
/// Each touching pair (and each sphere touching a wall or the floor) carries a tangential
/// spring ξ, the relative tangential displacement of the two surfaces at the contact since it
/// formed. With n the unit normal from i to j (or from i to the wall), Δc the displacement
/// of each centre and Δq = r·Δθ the rolling displacement since the last evaluation:
///
///     ξ += Δc_j − Δc_i − (Δq_i + Δq_j) × n,   then ξ ← ξ − (ξ·n)·n   (kept tangential)
///     F_t = k_t·ξ on i (−F_t on j),  capped: |F_t| ≤ μ·F_n, F_n = k·δ (ξ rescaled to the cap)
///     torque/r on i and on j alike: n × F_t
///
/// (a wall has Δc = Δq = 0). Below the cap the spring is elastic (energy ½·k_t·|ξ|², so FIRE
/// still minimises); at the cap the contact slides and dissipates. A contact that opens
/// forgets its spring. Rolling is free (no rolling resistance).
#include "relax_state.hpp"
#include "sgmp/pack/geometry.hpp"

namespace sgmp::engine {

/// Sizes the frictional arrays of `s` (all springs zero) and marks it frictional, with
/// k_t/k = `tangential_ratio` and μ = `friction`.
void enable_friction(State& s, double tangential_ratio, double friction);

/// Carries the springs of the pairs still listed over to the new neighbour list (the old
/// one in `s.previous`); pairs new to the list start with ξ = 0.
void carry_springs(State& s);

/// Adds the tangential forces and torques of every contact to s.f and s.g (s.g is reset
/// first), with normal stiffness k (m·g per length unit), k_t = s.tangential_ratio·k and
/// μ = s.friction, and clears the displacements since the last evaluation.
void add_tangential_forces(State& s, const Container& box, double k);

/// Multiplies every spring by `factor` (a new stage keeps F_t = k_t·ξ when k_t changes).
void scale_springs(State& s, double factor);

}  // namespace sgmp::engine
