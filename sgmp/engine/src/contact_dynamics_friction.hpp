#pragma once
/// @file contact_dynamics_friction.hpp
/// The frictional step of the contact-dynamics settling (contact_dynamics.hpp with
/// `friction` μ > 0). Internal to the engine.
///
/// Spheres are rigid with translation vᵢ and rotation ωᵢ, mass mᵢ and moment of inertia
/// Iᵢ = 0.4·mᵢ·rᵢ². A contact of normal n (from sphere a to its partner b) carries a force
/// on b inside the pyramid of its 8 edges Eₖ (coulomb_pyramid.hpp; inscribed in the Coulomb
/// cone, as in the frictional certificate), F = Σₖ βₖ·Eₖ with βₖ ≥ 0, applied at the contact
/// point (a: cₐ + rₐ·n, b: c_b − r_b·n); −F acts on a. Each edge is one row of the step's
/// problem, with the associated (dilatant) law of the frictional LP settling
/// (hard_sphere_settle.hpp):
///
///     0 ≤ pₖ  ⟂  g/h + Eₖ·(u_b − u_a) ≥ 0,
///     u_a = vₐ + ωₐ × (rₐ·n),   u_b = v_b + ω_b × (−r_b·n),
///
/// so J_k = [−Eₖ, −rₐ·qₖ] on a and [Eₖ, −r_b·qₖ] on b (translation, rotation), qₖ = n × Eₖ
/// (walls: the partner at rest). Each row has |Eₖ|² = 1 + μ'² and |qₖ|² = μ'², μ' = μ·cos(π/8).
/// Σₖ pₖ ≥ 0 is the normal impulse, so a contact of the step keeps the hard-sphere gap
/// as the frictionless rows do. The residual of sphere i asks force and torque to balance
/// and the sphere to be at rest: √(Rᶠᵢ² + (Rᵗᵢ/d)²), Rᶠᵢ = mᵢ·max(|vᵢ⁺ − vᵢ°|, |vᵢ⁺|)/h and
/// Rᵗᵢ = Iᵢ·|ωᵢ⁺|/h (each step starts without rotation), the certificate's measure.
#include <vector>

#include "contact_dynamics_state.hpp"

namespace sgmp::engine::contact_dynamics {

/// Sizes the rotation state and the kept impulses for friction μ > 0 (after the balls),
/// `stride` impulses kept per pair slot or wall: 8 edge rows, or 3 components of a vector.
void prepare_friction(Dynamics& s, double friction, std::size_t stride);

/// The step's edge rows: every contact `gather_contacts` found, 8 rows each, with the last
/// step's impulses.
void gather_edges(Dynamics& s);

/// v ← v° − h·ŷ, ω ← 0, then the warm-start impulses of the edge rows.
void start_edge_velocities(Dynamics& s);

/// Keeps the edge impulses for the next step's warm start, and each contact's normal
/// impulse Σₖ pₖ in its `Contact::p` (whose forces the step reports, as frictionless).
void store_edge_impulses(Dynamics& s);

/// The largest residual of the step (above), in m·g.
double edge_step_residual(const Dynamics& s);

// The edge rows' operations of the MPRGP template (contact_dynamics_mprgp.hpp).
double closing_velocity(const Dynamics& s, const EdgeRow& r);
void velocities_for(Dynamics& s, const std::vector<EdgeRow>& rows, const std::vector<double>& p);
double delassus_bound(const Dynamics& s, const std::vector<EdgeRow>& rows);
void delassus_times(const Dynamics& s, const std::vector<EdgeRow>& rows,
                    const std::vector<double>& x, std::vector<double>& out,
                    std::vector<V3>& scratch);
void ssor_apply(const Dynamics& s, const std::vector<EdgeRow>& rows, const std::vector<double>& x,
                const std::vector<double>& r, double omega, std::vector<double>& z,
                std::vector<V3>& scratch);
std::size_t scratch_size(const Dynamics& s, const std::vector<EdgeRow>& rows);

/// The MPRGP solve of the step's edge rows; returns the products with W.
int solve_edges(Dynamics& s, double tolerance, int max_products, double ssor);

}  // namespace sgmp::engine::contact_dynamics
