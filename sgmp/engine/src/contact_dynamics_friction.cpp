#include "contact_dynamics_friction.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

#include "contact_dynamics_mprgp.hpp"
#include "sgmp/engine/coulomb_pyramid.hpp"

namespace sgmp::engine::contact_dynamics {

namespace {

V3 to_v3(const Vec3& v) {
    return V3{v.x(), v.y(), v.z()};
}

/// Adds impulse `dp` along edge row r to the velocities `lin` and `ang` (one per sphere).
void add_impulse(const Dynamics& s, const EdgeRow& r, double dp, V3* lin, V3* ang) {
    const double ka = dp * s.inv_m[r.a];
    const double ta = dp * s.inv_i[r.a] * s.balls[r.a].r;
    lin[r.a].x -= ka * r.e.x;
    lin[r.a].y -= ka * r.e.y;
    lin[r.a].z -= ka * r.e.z;
    ang[r.a].x -= ta * r.q.x;
    ang[r.a].y -= ta * r.q.y;
    ang[r.a].z -= ta * r.q.z;
    if (r.b != kWall) {
        const double kb = dp * s.inv_m[r.b];
        const double tb = dp * s.inv_i[r.b] * s.balls[r.b].r;
        lin[r.b].x += kb * r.e.x;
        lin[r.b].y += kb * r.e.y;
        lin[r.b].z += kb * r.e.z;
        ang[r.b].x -= tb * r.q.x;
        ang[r.b].y -= tb * r.q.y;
        ang[r.b].z -= tb * r.q.z;
    }
}

/// J_r·(lin, ang): E·(lin_b − lin_a) − r_a·q·ang_a − r_b·q·ang_b.
double row_times(const Dynamics& s, const EdgeRow& r, const V3* lin, const V3* ang) {
    double u = -dot(r.e, lin[r.a]) - s.balls[r.a].r * dot(r.q, ang[r.a]);
    if (r.b != kWall) {
        u += dot(r.e, lin[r.b]) - s.balls[r.b].r * dot(r.q, ang[r.b]);
    }
    return u;
}

/// |J_r,i|²/mᵢ-like weight of sphere i in a row: |E|²/mᵢ + rᵢ²·|q|²/Iᵢ.
double sphere_weight(const Dynamics& s, const EdgeRow& r, std::uint32_t i) {
    return dot(r.e, r.e) * s.inv_m[i] + s.balls[i].r * s.balls[i].r * dot(r.q, r.q) * s.inv_i[i];
}

}  // namespace

void prepare_friction(Dynamics& s, double friction, std::size_t stride) {
    const std::size_t n = s.balls.size();
    s.friction = friction;
    s.stride = stride;
    s.w.assign(n, V3{});
    s.inv_i.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        s.inv_i[i] = s.inv_m[i] / (0.4 * s.balls[i].r * s.balls[i].r);
    }
    s.wall_p.assign(5 * n * s.stride, 0.0);
}

void gather_edges(Dynamics& s) {
    s.edges.clear();
    for (const Contact& c : s.contacts) {
        const Vec3 n(c.nx, c.ny, c.nz);
        const auto edges = coulomb_pyramid(n, s.friction);
        for (std::size_t k = 0; k < edges.size(); ++k) {
            EdgeRow r;
            r.a = c.a;
            r.b = c.b;
            r.e = to_v3(edges[k]);
            r.q = to_v3(n.cross(edges[k]));
            r.gap = c.gap;
            r.wall = c.wall;
            r.slot = static_cast<std::uint32_t>(c.slot * s.stride + k);
            r.p = kept_impulses(s, r.b)[r.slot];
            double weight = sphere_weight(s, r, r.a);
            if (r.b != kWall) {
                weight += sphere_weight(s, r, r.b);
            }
            r.inv_w = 1.0 / weight;
            s.edges.push_back(r);
        }
    }
}

void start_edge_velocities(Dynamics& s) {
    for (std::size_t i = 0; i < s.v.size(); ++i) {
        s.v[i] = V3{s.kept[i].x, s.kept[i].y - s.h, s.kept[i].z};
        s.w[i] = V3{};
    }
    for (const EdgeRow& r : s.edges) {
        if (r.p > 0.0) {
            add_impulse(s, r, r.p, s.v.data(), s.w.data());
        }
    }
}

void store_edge_impulses(Dynamics& s) {
    std::fill(s.pair_p.begin(), s.pair_p.end(), 0.0);
    std::fill(s.wall_p.begin(), s.wall_p.end(), 0.0);
    for (const EdgeRow& r : s.edges) {
        kept_impulses(s, r.b)[r.slot] = r.p;
    }
    // Each contact's normal impulse Σₖ pₖ (the edges of contact c are rows 8c … 8c + 7).
    for (std::size_t c = 0; c < s.contacts.size(); ++c) {
        double normal = 0.0;
        for (std::size_t k = 0; k < s.stride; ++k) {
            normal += s.edges[c * s.stride + k].p;
        }
        s.contacts[c].p = normal;
    }
}

double edge_step_residual(const Dynamics& s) {
    double largest = 0.0;
    for (std::size_t i = 0; i < s.v.size(); ++i) {
        const V3& v = s.v[i];
        const V3& k = s.kept[i];
        const V3 dv{v.x - k.x, v.y - k.y, v.z - k.z};
        const double force = std::sqrt(std::max(dot(v, v), dot(dv, dv))) / s.inv_m[i];
        const double torque = std::sqrt(dot(s.w[i], s.w[i])) / s.inv_i[i] / s.diameter;
        largest = std::max(largest, std::hypot(force, torque));
    }
    return largest / s.h;
}

double closing_velocity(const Dynamics& s, const EdgeRow& r) {
    return row_times(s, r, s.v.data(), s.w.data());
}

void velocities_for(Dynamics& s, const std::vector<EdgeRow>& rows, const std::vector<double>& p) {
    for (std::size_t i = 0; i < s.v.size(); ++i) {
        s.v[i] = V3{s.kept[i].x, s.kept[i].y - s.h, s.kept[i].z};
        s.w[i] = V3{};
    }
    for (std::size_t c = 0; c < rows.size(); ++c) {
        if (p[c] != 0.0) {
            add_impulse(s, rows[c], p[c], s.v.data(), s.w.data());
        }
    }
}

double delassus_bound(const Dynamics& s, const std::vector<EdgeRow>& rows) {
    std::vector<std::uint32_t> degree(s.v.size(), 0);
    for (const EdgeRow& r : rows) {
        ++degree[r.a];
        if (r.b != kWall) {
            ++degree[r.b];
        }
    }
    double bound = 0.0;
    for (const EdgeRow& r : rows) {
        double row = sphere_weight(s, r, r.a) * degree[r.a];
        if (r.b != kWall) {
            row += sphere_weight(s, r, r.b) * degree[r.b];
        }
        bound = std::max(bound, row);
    }
    return bound;
}

void delassus_times(const Dynamics& s, const std::vector<EdgeRow>& rows,
                    const std::vector<double>& x, std::vector<double>& out,
                    std::vector<V3>& scratch) {
    std::fill(scratch.begin(), scratch.end(), V3{});
    V3* lin = scratch.data();
    V3* ang = scratch.data() + s.v.size();
    for (std::size_t k = 0; k < rows.size(); ++k) {
        if (x[k] != 0.0) {
            add_impulse(s, rows[k], x[k], lin, ang);
        }
    }
    for (std::size_t k = 0; k < rows.size(); ++k) {
        out[k] = row_times(s, rows[k], lin, ang);
    }
}

void ssor_apply(const Dynamics& s, const std::vector<EdgeRow>& rows, const std::vector<double>& x,
                const std::vector<double>& r, double omega, std::vector<double>& z,
                std::vector<V3>& scratch) {
    std::fill(scratch.begin(), scratch.end(), V3{});
    std::fill(z.begin(), z.end(), 0.0);
    V3* lin = scratch.data();
    V3* ang = scratch.data() + s.v.size();
    const auto relax = [&](std::size_t k) {
        const double dz = omega * (r[k] - row_times(s, rows[k], lin, ang)) * rows[k].inv_w;
        z[k] += dz;
        add_impulse(s, rows[k], dz, lin, ang);
    };
    for (std::size_t k = rows.size(); k-- > 0;) {
        if (x[k] > 0.0) {
            relax(k);
        }
    }
    for (std::size_t k = 0; k < rows.size(); ++k) {
        if (x[k] > 0.0) {
            relax(k);
        }
    }
}

std::size_t scratch_size(const Dynamics& s, const std::vector<EdgeRow>&) {
    return 2 * s.v.size();
}

int solve_edges(Dynamics& s, double tolerance, int max_products, double ssor) {
    return solve_mprgp(s, s.edges, tolerance, max_products, ssor);
}

}  // namespace sgmp::engine::contact_dynamics
