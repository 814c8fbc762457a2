#pragma once
/// @file contact_dynamics_mprgp.hpp
/// One step's contact problem of the contact-dynamics settling (contact_dynamics.hpp),
///
///     min ½·pᵀWp + qᵀp  over p ≥ 0,   W = J·M⁻¹·Jᵀ,   q = g/h + J·v*,
///
/// by MPRGP (Dostál, Optimal Quadratic Programming Algorithms, Springer 2009, ch. 8), for
/// any kind of contact row: the frictionless normal rows (`Contact`) and the frictional
/// pyramid-edge rows (`EdgeRow`, contact_dynamics_friction.hpp). Internal to the engine.
///
/// A row type R comes with, found by argument-dependent lookup in the namespace
/// contact_dynamics:
///   - `closing_velocity(s, r)`: J_r·v of the present velocities;
///   - `velocities_for(s, rows, p)`: v = v* + M⁻¹·Jᵀ·p;
///   - `delassus_times(s, rows, x, out, scratch)`: out = W·x;
///   - `ssor_apply(s, rows, x, r, ω, z, scratch)`: one symmetric Gauss–Seidel sweep on W_FF;
///   - `delassus_bound(s, rows)`: an upper bound on W's largest eigenvalue;
///   - `scratch_size(s, rows)`: the V3 scratch the products need;
/// and each row holds its gap `gap` and impulse `p`.
#include <algorithm>
#include <cmath>
#include <vector>

#include "contact_dynamics_state.hpp"

namespace sgmp::engine::contact_dynamics {

/// Conjugate gradients on the rows carrying an impulse (the free set) while the chopped
/// gradient (of the rows at p = 0 that would press) stays below the free one (Γ = 1), a
/// feasible step and a projected gradient step of 1.9/L (expansion) where a CG step would
/// leave p ≥ 0, and a steepest step on the chopped gradient otherwise (proportioning). With
/// `ssor` > 0 the conjugate gradients are preconditioned in the face by a symmetric
/// Gauss–Seidel sweep over the free rows of relaxation `ssor` (ssor_apply). From the warm
/// start (the rows' p), until every projected gradient component is below `tolerance`·h (a
/// velocity: m·g·h/m); leaves the impulses in the rows and the velocities in `s`, and
/// returns the products with W.
template <class Row>
int solve_mprgp(Dynamics& s, std::vector<Row>& rows, double tolerance, int max_products,
                double ssor) {
    const std::size_t n = rows.size();
    const double inv_h = 1.0 / s.h;
    const double alpha_bar = 1.9 / std::max(delassus_bound(s, rows), 1e-300);
    std::vector<double> x(n), q(n), g(n), d(n), ad(n), free_g(n), z(n);
    std::vector<V3> scratch(scratch_size(s, rows));
    velocities_for(s, rows, std::vector<double>(n, 0.0));
    for (std::size_t c = 0; c < n; ++c) {
        x[c] = std::max(0.0, rows[c].p);
        q[c] = rows[c].gap * inv_h + closing_velocity(s, rows[c]);
    }
    const auto full_gradient = [&] {
        delassus_times(s, rows, x, g, scratch);
        for (std::size_t c = 0; c < n; ++c) {
            g[c] += q[c];
        }
    };
    // The free gradient φ and its preconditioned form z (z = φ without preconditioning).
    const auto free_part = [&] {
        for (std::size_t c = 0; c < n; ++c) {
            free_g[c] = x[c] > 0.0 ? g[c] : 0.0;
        }
        if (ssor > 0.0) {
            ssor_apply(s, rows, x, free_g, ssor, z, scratch);
        } else {
            z = free_g;
        }
    };
    // ‖β‖², φ̃ᵀφ and the largest projected gradient component.
    struct Split {
        double chopped = 0.0;
        double reduced = 0.0;
        double largest = 0.0;
    };
    const auto split = [&] {
        Split r;
        for (std::size_t c = 0; c < n; ++c) {
            if (x[c] > 0.0) {
                r.reduced += std::min(x[c] / alpha_bar, g[c]) * g[c];
                r.largest = std::max(r.largest, std::abs(g[c]));
            } else if (g[c] < 0.0) {
                r.chopped += g[c] * g[c];
                r.largest = std::max(r.largest, -g[c]);
            }
        }
        return r;
    };
    int products = 1;
    // The expansion step: a projected gradient step of length ᾱ on the free set, then the
    // gradient afresh and a new search direction from its free part.
    const auto expand = [&] {
        for (std::size_t c = 0; c < n; ++c) {
            x[c] = std::max(0.0, x[c] - alpha_bar * (x[c] > 0.0 ? g[c] : 0.0));
        }
        full_gradient();
        ++products;
        free_part();
        d = z;
    };
    full_gradient();
    free_part();
    d = z;
    const double bound = tolerance * s.h;
    while (products < max_products) {
        const Split now = split();
        if (now.largest <= bound) {
            break;
        }
        if (now.chopped <= now.reduced) {
            delassus_times(s, rows, d, ad, scratch);
            ++products;
            double dad = 0.0, gd = 0.0;
            for (std::size_t c = 0; c < n; ++c) {
                dad += d[c] * ad[c];
                gd += g[c] * d[c];
            }
            if (!(dad > 0.0) || !(gd > 0.0)) {  // no descent left along d: restart
                full_gradient();
                ++products;
                expand();
                continue;
            }
            const double a_cg = gd / dad;
            double a_f = INFINITY;
            for (std::size_t c = 0; c < n; ++c) {
                if (d[c] > 0.0) {
                    a_f = std::min(a_f, x[c] / d[c]);
                }
            }
            if (a_cg <= a_f) {
                for (std::size_t c = 0; c < n; ++c) {
                    x[c] -= a_cg * d[c];
                    g[c] -= a_cg * ad[c];
                }
                free_part();
                double zad = 0.0;
                for (std::size_t c = 0; c < n; ++c) {
                    zad += z[c] * ad[c];
                }
                const double gamma = zad / dad;
                for (std::size_t c = 0; c < n; ++c) {
                    d[c] = z[c] - gamma * d[c];
                }
            } else {
                for (std::size_t c = 0; c < n; ++c) {
                    x[c] = std::max(0.0, x[c] - a_f * d[c]);
                    g[c] -= a_f * ad[c];
                }
                expand();
            }
        } else {
            for (std::size_t c = 0; c < n; ++c) {
                z[c] = x[c] > 0.0 ? 0.0 : std::min(g[c], 0.0);  // β
            }
            delassus_times(s, rows, z, ad, scratch);
            ++products;
            double bab = 0.0, gb = 0.0;
            for (std::size_t c = 0; c < n; ++c) {
                bab += z[c] * ad[c];
                gb += g[c] * z[c];
            }
            const double a = bab > 0.0 ? gb / bab : alpha_bar;
            for (std::size_t c = 0; c < n; ++c) {
                x[c] = std::max(0.0, x[c] - a * z[c]);
                g[c] -= a * ad[c];
            }
            free_part();
            d = z;
        }
    }
    for (std::size_t c = 0; c < n; ++c) {
        rows[c].p = x[c];
    }
    velocities_for(s, rows, x);
    return products;
}

}  // namespace sgmp::engine::contact_dynamics
