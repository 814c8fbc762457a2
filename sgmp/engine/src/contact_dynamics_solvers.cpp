// The frictionless contact problem of one contact-dynamics step (contact_dynamics.hpp) and
// its three solvers: projected SOR, APGD and MPRGP over the normal rows, with the rows'
// products with the Delassus operator W that MPRGP needs.
#include "contact_dynamics_solvers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "contact_dynamics_mprgp.hpp"

namespace sgmp::engine::contact_dynamics {

/// One NSGS update of contact c; returns |Δp|.
inline double relax_contact(Dynamics& s, Contact& c, double inv_h, double omega) {
    const double u = normal_velocity(s, c);
    const double p = std::max(0.0, c.p - omega * (u + c.gap * inv_h) * c.inv_w);
    const double dp = p - c.p;
    if (dp == 0.0) {
        return 0.0;
    }
    c.p = p;
    apply(s, c, dp);
    return std::abs(dp);
}

/// Projected SOR sweeps over the contacts from the top of the pack down (the contacts are
/// stored bottom up, so a sweep carries each weight down in one pass), until no closing
/// force changes by more than `tolerance` (m·g); returns the sweeps taken.
int solve_sor(Dynamics& s, double tolerance, double omega, int max_sweeps) {
    const double inv_h = 1.0 / s.h;
    const double bound = tolerance * s.h;
    std::vector<Contact>& cs = s.contacts;
    for (int sweep = 1; sweep <= max_sweeps; ++sweep) {
        double largest = 0.0;
        for (auto c = cs.rbegin(); c != cs.rend(); ++c) {
            largest = std::max(largest, relax_contact(s, *c, inv_h, omega));
        }
        if (largest <= bound) {
            return sweep;
        }
    }
    return max_sweeps;
}

// The normal rows' operations of the MPRGP template (contact_dynamics_mprgp.hpp).

/// The velocities v* + M⁻¹·Jᵀ·p of impulses p (in contact order), v* = v° − h·ŷ.
void velocities_for(Dynamics& s, const std::vector<Contact>& rows, const std::vector<double>& p) {
    for (std::size_t i = 0; i < s.v.size(); ++i) {
        s.v[i] = V3{s.kept[i].x, s.kept[i].y - s.h, s.kept[i].z};
    }
    for (std::size_t c = 0; c < rows.size(); ++c) {
        if (p[c] != 0.0) {
            apply(s, rows[c], p[c]);
        }
    }
}

/// A bound on the largest eigenvalue of W (Gershgorin: each row's sum of |W_cd| is at most
/// Σ over its spheres of 1/mᵢ times the contacts on the sphere).
double delassus_bound(const Dynamics& s, const std::vector<Contact>& rows) {
    std::vector<std::uint32_t> degree(s.v.size(), 0);
    for (const Contact& c : rows) {
        ++degree[c.a];
        if (c.b != kWall) {
            ++degree[c.b];
        }
    }
    double bound = 0.0;
    for (const Contact& c : rows) {
        const double row =
            s.inv_m[c.a] * degree[c.a] + (c.b == kWall ? 0.0 : s.inv_m[c.b] * degree[c.b]);
        bound = std::max(bound, row);
    }
    return bound;
}

/// out = W·x (W = J·M⁻¹·Jᵀ) for impulses x in contact order; `scratch` holds M⁻¹·Jᵀ·x.
void delassus_times(const Dynamics& s, const std::vector<Contact>& rows,
                    const std::vector<double>& x, std::vector<double>& out,
                    std::vector<V3>& scratch) {
    std::fill(scratch.begin(), scratch.end(), V3{});
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const Contact& c = rows[k];
        if (x[k] == 0.0) {
            continue;
        }
        const double ka = x[k] * s.inv_m[c.a];
        scratch[c.a].x -= ka * c.nx;
        scratch[c.a].y -= ka * c.ny;
        scratch[c.a].z -= ka * c.nz;
        if (c.b != kWall) {
            const double kb = x[k] * s.inv_m[c.b];
            scratch[c.b].x += kb * c.nx;
            scratch[c.b].y += kb * c.ny;
            scratch[c.b].z += kb * c.nz;
        }
    }
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const Contact& c = rows[k];
        const V3& va = scratch[c.a];
        double u = -(c.nx * va.x + c.ny * va.y + c.nz * va.z);
        if (c.b != kWall) {
            const V3& vb = scratch[c.b];
            u += c.nx * vb.x + c.ny * vb.y + c.nz * vb.z;
        }
        out[k] = u;
    }
}

/// z ≈ W_FF⁻¹·r on the free contacts (x > 0; z = 0 elsewhere) by one symmetric Gauss–Seidel
/// sweep from z = 0, forward then backward over the contacts (SSOR with ω, a symmetric
/// positive definite preconditioner of W_FF); `scratch` holds M⁻¹·Jᵀ·z.
void ssor_apply(const Dynamics& s, const std::vector<Contact>& rows, const std::vector<double>& x,
                const std::vector<double>& r, double omega, std::vector<double>& z,
                std::vector<V3>& scratch) {
    std::fill(scratch.begin(), scratch.end(), V3{});
    std::fill(z.begin(), z.end(), 0.0);
    const auto relax = [&](std::size_t k) {
        const Contact& c = rows[k];
        V3& va = scratch[c.a];
        double wz = -(c.nx * va.x + c.ny * va.y + c.nz * va.z);
        if (c.b != kWall) {
            const V3& vb = scratch[c.b];
            wz += c.nx * vb.x + c.ny * vb.y + c.nz * vb.z;
        }
        const double dz = omega * (r[k] - wz) * c.inv_w;
        z[k] += dz;
        const double ka = dz * s.inv_m[c.a];
        va.x -= ka * c.nx;
        va.y -= ka * c.ny;
        va.z -= ka * c.nz;
        if (c.b != kWall) {
            V3& vb = scratch[c.b];
            const double kb = dz * s.inv_m[c.b];
            vb.x += kb * c.nx;
            vb.y += kb * c.ny;
            vb.z += kb * c.nz;
        }
    };
    const std::size_t n = rows.size();
    for (std::size_t k = n; k-- > 0;) {
        if (x[k] > 0.0) {
            relax(k);
        }
    }
    for (std::size_t k = 0; k < n; ++k) {
        if (x[k] > 0.0) {
            relax(k);
        }
    }
}

/// The scratch the products with W need: one velocity per sphere.
std::size_t scratch_size(const Dynamics& s, const std::vector<Contact>&) {
    return s.v.size();
}

/// The contact problem as min ½·pᵀWp + qᵀp over p ≥ 0 (its gradient Wp + q = g/h + u(p)),
/// by Nesterov's accelerated projected gradient with step 1/L (L: delassus_bound) and the
/// gradient restart of O'Donoghue & Candès (APGD, as in Chrono), from the warm start, until
/// no force changes by more than `tolerance` (m·g); returns the iterations.
int solve_apgd(Dynamics& s, double tolerance, int max_iterations) {
    const std::size_t n = s.contacts.size();
    const double inv_h = 1.0 / s.h;
    const double step = 1.0 / std::max(delassus_bound(s, s.contacts), 1e-300);
    std::vector<double> p(n), y(n), next(n);
    for (std::size_t c = 0; c < n; ++c) {
        p[c] = y[c] = s.contacts[c].p;
    }
    double theta = 1.0;
    int k = 1;
    for (; k <= max_iterations; ++k) {
        velocities_for(s, s.contacts, y);
        double largest = 0.0;
        double ascent = 0.0;  // gradient·(p_next − p) > 0: restart the momentum
        for (std::size_t c = 0; c < n; ++c) {
            const double grad = s.contacts[c].gap * inv_h + normal_velocity(s, s.contacts[c]);
            next[c] = std::max(0.0, y[c] - step * grad);
            largest = std::max(largest, std::abs(next[c] - p[c]));
            ascent += grad * (next[c] - p[c]);
        }
        const double theta_next = 0.5 * theta * (std::sqrt(theta * theta + 4.0) - theta);
        const double beta =
            ascent > 0.0 ? 0.0 : theta * (1.0 - theta) / (theta * theta + theta_next);
        theta = ascent > 0.0 ? 1.0 : theta_next;
        for (std::size_t c = 0; c < n; ++c) {
            y[c] = next[c] + beta * (next[c] - p[c]);
        }
        p.swap(next);
        if (largest <= tolerance * s.h) {
            break;
        }
    }
    for (std::size_t c = 0; c < n; ++c) {
        s.contacts[c].p = p[c];
    }
    velocities_for(s, s.contacts, p);
    return std::min(k, max_iterations);
}

int solve_normal_mprgp(Dynamics& s, double tolerance, int max_products, double ssor) {
    return solve_mprgp(s, s.contacts, tolerance, max_products, ssor);
}

}  // namespace sgmp::engine::contact_dynamics
