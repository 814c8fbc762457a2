#pragma once
/// @file contact_search.hpp
/// Two questions asked of the settled spheres (a SettledGrid) by the protocol and by both
/// contact models: where a falling sphere first touches something, and whether a place a
/// roll reached is clear.
///
/// A sphere of radius r falling straight down from c touches the settled sphere s (radius
/// r_s, horizontal centre distance h < r + r_s) at the height y_s + √((r + r_s)² − h²),
/// and the floor at floor + r; the first contact below is the highest of these. A height
/// above c.y (a rounding-level overlap) counts as touching now: the contact height is
/// capped at c.y.
#include <algorithm>
#include <cmath>
#include <limits>

#include "sgmp/engine/settled_grid.hpp"
#include "sgmp/pack/geometry.hpp"

namespace sgmp::engine {

/// The first contact of a straight fall.
struct FirstContact {
    double y = 0.0;        ///< the centre's height at the contact
    bool on_floor = true;  ///< the floor is met first
    Sphere support;        ///< the sphere touched first (when not on the floor)
};

/// Height at which a sphere of radius r falling from c first touches s, capped at c.y;
/// negative infinity when s is no obstacle: outside the fall column (h ≥ r + r_s), or
/// with its centre above c.y − level_margin·(r + r_s). The protocol counts every sphere
/// not above the faller (margin 0); a roll leaving a support at its equator passes the
/// spheres it touches there (margin 10⁻⁹), which would otherwise stop the fall at once.
/// (Inline: the fall evaluates it for every sphere of the local list at every move.)
inline double contact_height(const Vec3& c, double r, const Sphere& s, double level_margin = 0.0) {
    const double contact = r + s.r;
    if (s.y > c.y() - level_margin * contact) {
        return -std::numeric_limits<double>::infinity();
    }
    const double dx = c.x() - s.x;
    const double dz = c.z() - s.z;
    const double h2 = dx * dx + dz * dz;
    const double contact2 = contact * contact;
    if (h2 >= contact2) {
        return -std::numeric_limits<double>::infinity();
    }
    return std::min(s.y + std::sqrt(contact2 - h2), c.y());
}

/// The first contact below c of a sphere of radius r falling straight down among the
/// spheres of `grid` (radii ≤ r_max) onto `container`'s floor: the highest contact
/// height, scanning the column below layer by layer from the top and stopping once no
/// lower layer can hold a higher one. A sphere found earlier wins a tie.
FirstContact first_contact_below(const SettledGrid& grid, const Container& container, double r_max,
                                 const Vec3& c, double r, double level_margin = 0.0);

/// The overlap guard after a roll: the largest overlap, relative to the contact distance
/// r + r_k, that a place reached by a closed-form roll may have with a settled sphere and
/// still count as touching. Roll legs end at exact contact roots, so a genuine overlap is
/// rounding (≲ 10⁻¹⁵); the guard only refuses a leg whose end rounding has pushed too far
/// into a neighbour near tangency, where the protocol itself would not go.
inline constexpr double kRollOverlapTolerance = 1e-10;

/// True when a sphere of radius r centred at p lies inside `container` (crossing it by at
/// most 10⁻¹²·r) and overlaps no sphere k of `grid` (radii ≤ r_max) by more than
/// `tolerance`·(r + r_k).
bool clear_at(const SettledGrid& grid, const Container& container, double r_max, const Vec3& p,
              double r, double tolerance = kRollOverlapTolerance);

}  // namespace sgmp::engine
