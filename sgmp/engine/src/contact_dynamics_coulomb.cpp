// The frictional contact problem of one contact-dynamics step, solved contact by contact
// with the closed-form local Coulomb solve (contact_dynamics_coulomb.hpp).
#include "contact_dynamics_coulomb.hpp"

#include <algorithm>
#include <cmath>

namespace sgmp::engine::contact_dynamics {

namespace {

V3 cross(const V3& a, const V3& b) {
    return V3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

V3 normal_of(const Contact& c) {
    return V3{c.nx, c.ny, c.nz};
}

/// Adds impulse dP of contact c (on b; −dP on a) to the spheres' velocities.
void push(Dynamics& s, const Contact& c, const V3& n, const V3& dp) {
    const V3 t = cross(n, dp);
    const double ka = s.inv_m[c.a], ta = s.balls[c.a].r * s.inv_i[c.a];
    s.v[c.a] = V3{s.v[c.a].x - ka * dp.x, s.v[c.a].y - ka * dp.y, s.v[c.a].z - ka * dp.z};
    s.w[c.a] = V3{s.w[c.a].x - ta * t.x, s.w[c.a].y - ta * t.y, s.w[c.a].z - ta * t.z};
    if (c.b != kWall) {
        const double kb = s.inv_m[c.b], tb = s.balls[c.b].r * s.inv_i[c.b];
        s.v[c.b] = V3{s.v[c.b].x + kb * dp.x, s.v[c.b].y + kb * dp.y, s.v[c.b].z + kb * dp.z};
        s.w[c.b] = V3{s.w[c.b].x - tb * t.x, s.w[c.b].y - tb * t.y, s.w[c.b].z - tb * t.z};
    }
}

/// u = u_b − u_a at the contact point (above).
V3 contact_velocity(const Dynamics& s, const Contact& c, const V3& n) {
    const V3 wa = cross(s.w[c.a], n);
    const double ra = s.balls[c.a].r;
    V3 u{-s.v[c.a].x - ra * wa.x, -s.v[c.a].y - ra * wa.y, -s.v[c.a].z - ra * wa.z};
    if (c.b != kWall) {
        const V3 wb = cross(s.w[c.b], n);
        const double rb = s.balls[c.b].r;
        u = V3{u.x + s.v[c.b].x - rb * wb.x, u.y + s.v[c.b].y - rb * wb.y,
               u.z + s.v[c.b].z - rb * wb.z};
    }
    return u;
}

/// P projected onto the cone |P_t| ≤ μ·Pₙ along the tangent plane (Pₙ < 0: 0).
V3 onto_cone(const V3& p, const V3& n, double mu) {
    const double pn = dot(p, n);
    if (pn <= 0.0) {
        return V3{};
    }
    const V3 pt{p.x - pn * n.x, p.y - pn * n.y, p.z - pn * n.z};
    const double t = std::sqrt(dot(pt, pt));
    const double scale = t > mu * pn ? mu * pn / t : 1.0;
    return V3{pn * n.x + scale * pt.x, pn * n.y + scale * pt.y, pn * n.z + scale * pt.z};
}

/// One local update of contact k; returns |ΔP|.
double relax_coulomb(Dynamics& s, std::size_t k, double inv_h, double omega) {
    const Contact& c = s.contacts[k];
    const V3 n = normal_of(c);
    V3& p = s.impulse[k];
    double wn = s.inv_m[c.a];
    double wt = wn + s.balls[c.a].r * s.balls[c.a].r * s.inv_i[c.a];
    if (c.b != kWall) {
        wn += s.inv_m[c.b];
        wt += s.inv_m[c.b] + s.balls[c.b].r * s.balls[c.b].r * s.inv_i[c.b];
    }
    const V3 u = contact_velocity(s, c, n);
    const double pn = dot(p, n);
    const V3 pt{p.x - pn * n.x, p.y - pn * n.y, p.z - pn * n.z};
    const V3 uf{u.x - wn * pn * n.x - wt * pt.x, u.y - wn * pn * n.y - wt * pt.y,
                u.z - wn * pn * n.z - wt * pt.z};
    const double ufn = dot(uf, n);
    V3 target{};
    if (ufn + c.gap * inv_h < 0.0) {
        const double tn = -(ufn + c.gap * inv_h) / wn;
        V3 tt{-(uf.x - ufn * n.x) / wt, -(uf.y - ufn * n.y) / wt, -(uf.z - ufn * n.z) / wt};
        const double t = std::sqrt(dot(tt, tt));
        if (t > s.friction * tn) {
            const double scale = s.friction * tn / t;
            tt = V3{scale * tt.x, scale * tt.y, scale * tt.z};
        }
        target = V3{tn * n.x + tt.x, tn * n.y + tt.y, tn * n.z + tt.z};
    }
    if (omega != 1.0) {
        target = onto_cone(V3{p.x + omega * (target.x - p.x), p.y + omega * (target.y - p.y),
                              p.z + omega * (target.z - p.z)},
                           n, s.friction);
    }
    const V3 dp{target.x - p.x, target.y - p.y, target.z - p.z};
    const double size = std::sqrt(dot(dp, dp));
    if (size > 0.0) {
        p = target;
        push(s, c, n, dp);
    }
    return size;
}

}  // namespace

void gather_coulomb(Dynamics& s) {
    s.impulse.resize(s.contacts.size());
    for (std::size_t k = 0; k < s.contacts.size(); ++k) {
        const Contact& c = s.contacts[k];
        const std::vector<double>& kept = kept_impulses(s, c.b);
        const std::size_t at = c.slot * s.stride;
        // The kept impulse, put back in the present cone (the normal has turned a little).
        s.impulse[k] =
            onto_cone(V3{kept[at], kept[at + 1], kept[at + 2]}, normal_of(c), s.friction);
    }
}

void start_coulomb_velocities(Dynamics& s) {
    for (std::size_t i = 0; i < s.v.size(); ++i) {
        s.v[i] = V3{s.kept[i].x, s.kept[i].y - s.h, s.kept[i].z};
        s.w[i] = V3{};
    }
    for (std::size_t k = 0; k < s.contacts.size(); ++k) {
        if (dot(s.impulse[k], s.impulse[k]) > 0.0) {
            push(s, s.contacts[k], normal_of(s.contacts[k]), s.impulse[k]);
        }
    }
}

int solve_coulomb(Dynamics& s, double tolerance, double omega, int max_sweeps) {
    const double inv_h = 1.0 / s.h;
    const double bound = tolerance * s.h;
    const std::size_t m = s.contacts.size();
    for (int sweep = 1; sweep <= max_sweeps; ++sweep) {
        double largest = 0.0;
        if (sweep % 2 == 1) {
            for (std::size_t k = m; k-- > 0;) {
                largest = std::max(largest, relax_coulomb(s, k, inv_h, omega));
            }
        } else {
            for (std::size_t k = 0; k < m; ++k) {
                largest = std::max(largest, relax_coulomb(s, k, inv_h, omega));
            }
        }
        if (largest <= bound) {
            return sweep;
        }
    }
    return max_sweeps;
}

void store_coulomb_impulses(Dynamics& s) {
    std::fill(s.pair_p.begin(), s.pair_p.end(), 0.0);
    std::fill(s.wall_p.begin(), s.wall_p.end(), 0.0);
    for (std::size_t k = 0; k < s.contacts.size(); ++k) {
        Contact& c = s.contacts[k];
        std::vector<double>& kept = kept_impulses(s, c.b);
        const std::size_t at = c.slot * s.stride;
        kept[at] = s.impulse[k].x;
        kept[at + 1] = s.impulse[k].y;
        kept[at + 2] = s.impulse[k].z;
        c.p = dot(s.impulse[k], normal_of(c));
    }
}

}  // namespace sgmp::engine::contact_dynamics
