#pragma once
/// @file contact_dynamics_solvers.hpp
/// The frictionless contact problem of one contact-dynamics step (contact_dynamics.hpp): the
/// impulses p ≥ 0 on the step's contacts (`Dynamics::contacts`, warm-started), by one of
/// three solvers, each until no force changes by more than `tolerance` (m·g). Each leaves
/// the impulses in the contacts and the velocities in `s`. Internal to the engine.
#include "contact_dynamics_state.hpp"

namespace sgmp::engine::contact_dynamics {

/// Projected SOR sweeps (relaxation `omega`) over the contacts from the top of the pack
/// down; returns the sweeps taken (at most `max_sweeps`).
int solve_sor(Dynamics& s, double tolerance, double omega, int max_sweeps);

/// Nesterov's accelerated projected gradient with gradient restart (APGD); returns the
/// iterations (at most `max_iterations`).
int solve_apgd(Dynamics& s, double tolerance, int max_iterations);

/// MPRGP over the normal rows (contact_dynamics_mprgp.hpp), preconditioned by a symmetric
/// Gauss–Seidel sweep of relaxation `ssor` when `ssor` > 0; returns the products with W.
int solve_normal_mprgp(Dynamics& s, double tolerance, int max_products, double ssor);

}  // namespace sgmp::engine::contact_dynamics
