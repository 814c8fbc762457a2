#include "sgmp/engine/contact_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sgmp::engine {

FirstContact first_contact_below(const SettledGrid& grid, const Container& container, double r_max,
                                 const Vec3& c, double r, double level_margin) {
    FirstContact result{container.floor + r, true, Sphere{}};
    if (grid.layers() == 0) {
        return result;
    }
    const double reach = r + r_max;
    const CellRange xs = grid.x_range(c.x() - reach, c.x() + reach);
    const CellRange zs = grid.z_range(c.z() - reach, c.z() + reach);
    for (int l = std::min(grid.layer_of(c.y()), grid.layers() - 1); l >= 0; --l) {
        // Every sphere in layer l or below has y_j < bottom(l + 1), so its contact height
        // is below bottom(l + 1) + r + r_max: nothing lower can beat the best found.
        if (grid.layer_bottom(l + 1) + reach <= result.y) {
            break;
        }
        grid.for_each_in_layer(l, xs, zs, [&](const Sphere& s) {
            const double y = contact_height(c, r, s, level_margin);
            if (y > result.y) {
                result = FirstContact{y, false, s};
            }
        });
    }
    return result;
}

bool clear_at(const SettledGrid& grid, const Container& container, double r_max, const Vec3& p,
              double r, double tolerance) {
    if (container.penetration(p, r) > 1e-12 * r) {
        return false;
    }
    bool clear = true;
    const Vec3 span = Vec3::Constant(r + r_max);
    grid.for_each_in_box(p - span, p + span, [&](const Sphere& s) {
        const double gap = (p - Vec3(s.x, s.y, s.z)).norm() - (r + s.r);
        clear = clear && gap >= -tolerance * (r + s.r);
    });
    return clear;
}

}  // namespace sgmp::engine
