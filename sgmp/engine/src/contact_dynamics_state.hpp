#pragma once
/// @file contact_dynamics_state.hpp
/// The pack a contact-dynamics settling moves (contact_dynamics.hpp) and the contacts of
/// one step, Internal to the engine.
#include <cstdint>
#include <limits>
#include <vector>

#include "sgmp/engine/neighbour_list.hpp"
#include "sgmp/pack/geometry.hpp"

namespace sgmp::engine::contact_dynamics {

/// Partner index of a wall or floor contact.
constexpr std::uint32_t kWall = std::numeric_limits<std::uint32_t>::max();

struct V3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
};

/// One contact of a step: spheres a and b (b = kWall: a's wall `wall`), the unit normal from
/// a to its partner, the gap, 1/W and the impulse p ≥ 0; `slot` is the pair's neighbour-list
/// slot, or 5·a + wall for a wall (where its impulse is kept between steps).
struct Contact {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    double nx = 0.0;
    double ny = 0.0;
    double nz = 0.0;
    double gap = 0.0;
    double inv_w = 0.0;
    double p = 0.0;
    std::uint32_t slot = 0;
    std::uint32_t wall = 0;
};

/// One edge row of a frictional contact (contact_dynamics_friction.hpp): the pyramid edge
/// E = Eₖ (coulomb_pyramid.hpp) of the contact's normal n from a to its partner,
/// q = n × E, the contact's gap, 1/W_rr and the impulse p ≥ 0 along E; `slot` indexes the
/// kept impulses (8 per pair slot or wall, as `Contact::slot` times 8, plus k).
struct EdgeRow {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    V3 e;
    V3 q;
    double gap = 0.0;
    double inv_w = 0.0;
    double p = 0.0;
    std::uint32_t slot = 0;
    std::uint32_t wall = 0;
};

/// The pack being settled, in an internal order (bottom up by cells of side d) that keeps
/// neighbours close in memory and lets a forward sweep carry weights down.
struct Dynamics {
    std::vector<Ball> balls;
    std::vector<V3> v;
    std::vector<V3> kept;  ///< velocity kept from the last step (0: the sphere starts at rest)
    std::vector<double> inv_m;
    std::vector<std::uint32_t> particle;  ///< index in the caller's vector
    std::vector<V3> at_build;             ///< positions when the list was built
    NeighbourList list;
    NeighbourList previous;
    std::vector<double> pair_p;  ///< impulse per neighbour-list slot
    std::vector<double> wall_p;  ///< impulse per sphere and wall (5 each)
    std::vector<Contact> contacts;
    /// Frictional settling (friction > 0): angular velocities, inverse moments of inertia
    /// (a solid sphere: 1/(0.4·m·r²)) and the step's edge rows (MPRGP); pair_p and wall_p
    /// then keep `stride` = 8 impulses per slot.
    double friction = 0.0;
    std::size_t stride = 1;
    std::vector<V3> w;
    std::vector<double> inv_i;
    std::vector<EdgeRow> edges;
    /// Frictional settling by NSGS (contact_dynamics_coulomb.hpp): each contact's impulse
    /// vector on its partner b; pair_p and wall_p then keep `stride` = 3 components per slot.
    std::vector<V3> impulse;
    double diameter = 0.0;
    Container box;
    double h = 0.0;
    double skin = 0.0;
    double cap = 0.0;  ///< largest displacement per step
};

inline double dot(const V3& a, const V3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// The impulses kept between steps for a contact whose partner is `b`: per wall
/// (`Dynamics::wall_p`) or per neighbour-list pair slot (`Dynamics::pair_p`).
inline std::vector<double>& kept_impulses(Dynamics& s, std::uint32_t b) {
    return b == kWall ? s.wall_p : s.pair_p;
}

/// Adds impulse `dp` of contact c to its spheres' velocities (a pushed along −n).
inline void apply(Dynamics& s, const Contact& c, double dp) {
    V3& va = s.v[c.a];
    const double ka = dp * s.inv_m[c.a];
    va.x -= ka * c.nx;
    va.y -= ka * c.ny;
    va.z -= ka * c.nz;
    if (c.b != kWall) {
        V3& vb = s.v[c.b];
        const double kb = dp * s.inv_m[c.b];
        vb.x += kb * c.nx;
        vb.y += kb * c.ny;
        vb.z += kb * c.nz;
    }
}

/// The closing velocity u_c = n_c·(v_b − v_a) of contact c (walls: −n_c·v_a).
inline double normal_velocity(const Dynamics& s, const Contact& c) {
    const V3& va = s.v[c.a];
    double u = -(c.nx * va.x + c.ny * va.y + c.nz * va.z);
    if (c.b != kWall) {
        const V3& vb = s.v[c.b];
        u += c.nx * vb.x + c.ny * vb.y + c.nz * vb.z;
    }
    return u;
}

/// J_c·v of contact c: its closing velocity (contact_dynamics_mprgp.hpp).
inline double closing_velocity(const Dynamics& s, const Contact& c) {
    return normal_velocity(s, c);
}

}  // namespace sgmp::engine::contact_dynamics
