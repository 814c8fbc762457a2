#pragma once
/// @file contact_dynamics_coulomb.hpp
/// The frictional step of the contact-dynamics settling solved contact by contact
/// (contact_dynamics.hpp with `friction` μ > 0 and the `Sor` solver): non-smooth
/// Gauss–Seidel over the contacts with an exact local Coulomb solve, the NSGS of LMGC90 and
/// of Siconos' fc3d (Jean 1999). Internal to the engine.
///
/// Spheres are rigid (vᵢ, ωᵢ; mᵢ, Iᵢ = 0.4·mᵢ·rᵢ²). Contact c of normal n (from a to b)
/// carries the impulse P on b (−P on a) at the contact point; b's point moves with
/// u_b = v_b − r_b·ω_b × n, a's with u_a = vₐ + rₐ·ωₐ × n, and u = u_b − u_a. For spheres
/// the contact's own Delassus block is diagonal in (n, tangent plane):
///
///     Δu = W_n·Pₙ·n + W_t·P_t,   W_n = 1/mₐ + 1/m_b,   W_t = W_n + rₐ²/Iₐ + r_b²/I_b
///
/// (W_t = 3.5·W_n; walls: a's terms only), so the local problem, Signorini with the gap as a
/// position correction and Coulomb's law at μ (non-associated: a sliding contact does not
/// dilate), has a closed-form solution. With u_f = u − W_n·Pₙ·n − W_t·P_t the velocity
/// without the contact's own impulse, ũₙ = n·u_f + g/h and u_ft its tangential part:
///
///     ũₙ ≥ 0:   P = 0                                          (opens)
///     else:     Pₙ = −ũₙ/W_n,  P_t = −u_ft/W_t                  (sticks)
///               and if |P_t| > μ·Pₙ:  P_t = −μ·Pₙ·u_ft/|u_ft|   (slides)
///
/// (the sliding tangential velocity after the impulse stays parallel to u_ft because W_t
/// is isotropic). A sweep visits the contacts from the top of the pack down, then back up,
/// each update over-relaxed by ω (`relaxation`) and projected onto the cone
/// |P_t| ≤ μ·Pₙ; it ends when no contact's force |ΔP|/h changes by more than the
/// tolerance. Every force the step reports lies in the Coulomb cone at μ.
#include "contact_dynamics_state.hpp"

namespace sgmp::engine::contact_dynamics {

/// The step's impulse vectors P (one per contact `gather_contacts` found), warm-started
/// from the kept impulses (3 world components per slot, `Dynamics::stride` = 3).
void gather_coulomb(Dynamics& s);

/// v ← v° − h·ŷ, ω ← 0, then the warm-start impulses.
void start_coulomb_velocities(Dynamics& s);

/// Symmetric NSGS sweeps (relaxation `omega`, in (0, 2)) until no force changes by more
/// than `tolerance` (m·g); returns the sweeps taken (at most `max_sweeps`).
int solve_coulomb(Dynamics& s, double tolerance, double omega, int max_sweeps);

/// Keeps the impulses for the next step and each contact's normal impulse n·P in
/// `Contact::p`.
void store_coulomb_impulses(Dynamics& s);

}  // namespace sgmp::engine::contact_dynamics
