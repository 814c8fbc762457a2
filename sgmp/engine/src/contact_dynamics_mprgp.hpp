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

/// The state of one MPRGP solve (solve_mprgp): the impulses x, the linear term q, the
/// gradient g = Wx + q, the search direction d and the products' scratch.
template <class Row>
class Mprgp {
  public:
    /// The problem of `rows` from their warm start, with its first gradient and direction.
    Mprgp(Dynamics& s, std::vector<Row>& rows, double ssor)
        : s_(s),
          rows_(rows),
          n_(rows.size()),
          ssor_(ssor),
          alpha_bar_(1.9 / std::max(delassus_bound(s, rows), 1e-300)),
          x_(n_),
          q_(n_),
          g_(n_),
          d_(n_),
          ad_(n_),
          free_g_(n_),
          z_(n_),
          scratch_(scratch_size(s, rows)) {
        const double inv_h = 1.0 / s.h;
        velocities_for(s, rows, std::vector<double>(n_, 0.0));
        for (std::size_t c = 0; c < n_; ++c) {
            x_[c] = std::max(0.0, rows[c].p);
            q_[c] = rows[c].gap * inv_h + closing_velocity(s, rows[c]);
        }
        full_gradient();
        free_part();
        d_ = z_;
    }

    /// Iterates until every projected gradient component is at most `bound` or the products
    /// with W reach `max_products`.
    void run(double bound, int max_products) {
        while (products_ < max_products) {
            const Split now = split();
            if (now.largest <= bound) {
                break;
            }
            if (now.chopped <= now.reduced) {
                conjugate_gradient_step();
            } else {
                proportioning_step();
            }
        }
    }

    /// Leaves the impulses in the rows and their velocities in the pack; returns the products
    /// with W.
    int finish() {
        for (std::size_t c = 0; c < n_; ++c) {
            rows_[c].p = x_[c];
        }
        velocities_for(s_, rows_, x_);
        return products_;
    }

  private:
    /// ‖β‖², φ̃ᵀφ and the largest projected gradient component.
    struct Split {
        double chopped = 0.0;
        double reduced = 0.0;
        double largest = 0.0;
    };

    /// g = Wx + q.
    void full_gradient() {
        delassus_times(s_, rows_, x_, g_, scratch_);
        for (std::size_t c = 0; c < n_; ++c) {
            g_[c] += q_[c];
        }
    }

    /// The free gradient φ and its preconditioned form z (z = φ without preconditioning).
    void free_part() {
        for (std::size_t c = 0; c < n_; ++c) {
            free_g_[c] = x_[c] > 0.0 ? g_[c] : 0.0;
        }
        if (ssor_ > 0.0) {
            ssor_apply(s_, rows_, x_, free_g_, ssor_, z_, scratch_);
        } else {
            z_ = free_g_;
        }
    }

    /// The chopped and reduced free gradients' measures and the largest component.
    Split split() const {
        Split r;
        for (std::size_t c = 0; c < n_; ++c) {
            if (x_[c] > 0.0) {
                r.reduced += std::min(x_[c] / alpha_bar_, g_[c]) * g_[c];
                r.largest = std::max(r.largest, std::abs(g_[c]));
            } else if (g_[c] < 0.0) {
                r.chopped += g_[c] * g_[c];
                r.largest = std::max(r.largest, -g_[c]);
            }
        }
        return r;
    }

    /// The expansion step: a projected gradient step of length ᾱ on the free set, then the
    /// gradient afresh and a new search direction from its free part.
    void expand() {
        for (std::size_t c = 0; c < n_; ++c) {
            x_[c] = std::max(0.0, x_[c] - alpha_bar_ * (x_[c] > 0.0 ? g_[c] : 0.0));
        }
        full_gradient();
        ++products_;
        free_part();
        d_ = z_;
    }

    /// The largest step along d that keeps x ≥ 0.
    double feasible_step() const {
        double a_f = INFINITY;
        for (std::size_t c = 0; c < n_; ++c) {
            if (d_[c] > 0.0) {
                a_f = std::min(a_f, x_[c] / d_[c]);
            }
        }
        return a_f;
    }

    /// A conjugate gradient step along d, cut to the feasible step (then an expansion) where
    /// it would leave x ≥ 0; a restart where no descent is left along d.
    void conjugate_gradient_step() {
        delassus_times(s_, rows_, d_, ad_, scratch_);
        ++products_;
        double dad = 0.0, gd = 0.0;
        for (std::size_t c = 0; c < n_; ++c) {
            dad += d_[c] * ad_[c];
            gd += g_[c] * d_[c];
        }
        if (!(dad > 0.0) || !(gd > 0.0)) {  // no descent left along d: restart
            full_gradient();
            ++products_;
            expand();
            return;
        }
        const double a_cg = gd / dad;
        const double a_f = feasible_step();
        if (a_cg <= a_f) {
            for (std::size_t c = 0; c < n_; ++c) {
                x_[c] -= a_cg * d_[c];
                g_[c] -= a_cg * ad_[c];
            }
            free_part();
            double zad = 0.0;
            for (std::size_t c = 0; c < n_; ++c) {
                zad += z_[c] * ad_[c];
            }
            const double gamma = zad / dad;
            for (std::size_t c = 0; c < n_; ++c) {
                d_[c] = z_[c] - gamma * d_[c];
            }
        } else {
            for (std::size_t c = 0; c < n_; ++c) {
                x_[c] = std::max(0.0, x_[c] - a_f * d_[c]);
                g_[c] -= a_f * ad_[c];
            }
            expand();
        }
    }

    /// A steepest step on the chopped gradient β (proportioning), projected onto x ≥ 0.
    void proportioning_step() {
        for (std::size_t c = 0; c < n_; ++c) {
            z_[c] = x_[c] > 0.0 ? 0.0 : std::min(g_[c], 0.0);  // β
        }
        delassus_times(s_, rows_, z_, ad_, scratch_);
        ++products_;
        double bab = 0.0, gb = 0.0;
        for (std::size_t c = 0; c < n_; ++c) {
            bab += z_[c] * ad_[c];
            gb += g_[c] * z_[c];
        }
        const double a = bab > 0.0 ? gb / bab : alpha_bar_;
        for (std::size_t c = 0; c < n_; ++c) {
            x_[c] = std::max(0.0, x_[c] - a * z_[c]);
            g_[c] -= a * ad_[c];
        }
        free_part();
        d_ = z_;
    }

    Dynamics& s_;
    std::vector<Row>& rows_;
    std::size_t n_;
    double ssor_;
    double alpha_bar_;
    std::vector<double> x_, q_, g_, d_, ad_, free_g_, z_;
    std::vector<V3> scratch_;
    int products_ = 1;
};

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
    Mprgp<Row> solve(s, rows, ssor);
    solve.run(tolerance * s.h, max_products);
    return solve.finish();
}

}  // namespace sgmp::engine::contact_dynamics
