#pragma once
/// @file geometry.hpp
/// The testbed of the thesis (chapter 3): the unit control volume centred at the origin
/// inside a 1.25-wide open-topped container, and the sizing rule for monodisperse packs.

#include <cmath>
#include <cstddef>
#include <string>

#include "sgmp/pack/particle.hpp"

namespace sgmp {

/// Axis-aligned box [lo, hi]. An infinite `hi.y()` is allowed (an open top).
struct Box {
    Vec3 lo = Vec3::Zero();
    Vec3 hi = Vec3::Zero();

    [[nodiscard]] double volume() const { return (hi - lo).prod(); }
    [[nodiscard]] bool contains(const Vec3& p) const {
        return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
    }
    /// True when `inner` lies entirely within this box.
    [[nodiscard]] bool contains(const Box& inner) const {
        return (inner.lo.array() >= lo.array()).all() && (inner.hi.array() <= hi.array()).all();
    }
};

/// Side of the control volume (the unit cube [-0.5, 0.5]^3).
inline constexpr double kControlSide = 1.0;
/// Side of the container (the thesis' "expanded volume").
inline constexpr double kContainerSide = 1.25;
/// Target packing fraction of every thesis run.
inline constexpr double kThesisPhiTarget = 0.63;
/// Densest packing of equal spheres, π/(3√2) = 0.740480489…, to five decimals: no target
/// packing fraction may exceed it (every part checks against this one bound).
inline constexpr double kMaxPhiTarget = 0.74048;
/// Largest particle count any part accepts: a pack, a pour, a measured file.
inline constexpr std::size_t kMaxCount = 10'000'000;

/// The container: walls at x = x_min, x_max and z = z_min, z_max, a floor at y = floor,
/// no lid. A particle is inside when its sphere lies between the walls and above the floor.
/// With periodic sides (`sides=periodic` in a pack's header) x and z are periodic with
/// periods x_max − x_min and z_max − z_min: there are no walls, only the floor, and a
/// centre belongs in [x_min, x_max) × [z_min, z_max).
struct Container {
    double x_min = -0.625;
    double x_max = 0.625;
    double z_min = -0.625;
    double z_max = 0.625;
    double floor = -0.625;
    bool periodic = false;  ///< x and z periodic (not part of to_string: the `sides` key)

    /// The five numbers "x_min x_max z_min z_max floor" as written in pack headers.
    [[nodiscard]] std::string to_string() const;
    /// Parses the text of `to_string`; throws std::invalid_argument naming the text.
    static Container parse(const std::string& text);

    /// Largest amount by which the sphere crosses a wall or the floor (0 when inside); with
    /// periodic sides, the floor only.
    [[nodiscard]] double penetration(const Vec3& center, double radius) const;
    /// The centre moved by whole periods into [x_min, x_max) × [z_min, z_max) when periodic;
    /// unchanged otherwise.
    [[nodiscard]] Vec3 wrapped(const Vec3& center) const;
    /// Moves the lateral parts (dx, dz) of a separation of two centres by whole periods to
    /// the nearest image, |dx| ≤ period/2 (likewise z), when periodic; leaves them otherwise.
    /// The minimum-image pair is the pair when the cell is over twice the pair's reach.
    void to_nearest_image(double& dx, double& dz) const {
        if (periodic) {
            const double lx = x_max - x_min;
            const double lz = z_max - z_min;
            dx -= lx * std::nearbyint(dx / lx);
            dz -= lz * std::nearbyint(dz / lz);
        }
    }
    /// The container as a box reaching up to `top`.
    [[nodiscard]] Box box_up_to(double top) const;
};

/// The thesis' control volume, [-0.5, 0.5]^3.
Box control_volume();

/// Sizing rule of the thesis: N/3 spheres fill the control volume at `phi_target`,
/// (N/3)·(π/6)·d³ = φ*  ⇒  d = (18 φ* / (π N))^(1/3).
double diameter_for_count(std::size_t count, double phi_target = kThesisPhiTarget);

}  // namespace sgmp
