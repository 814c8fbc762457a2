#include "sgmp/engine/settled_grid.hpp"

#include <algorithm>
#include <cmath>

namespace sgmp::engine {

double lowest_free_height(const SettledGrid& grid, double x, double z, double r, double r_max,
                          double from, std::vector<std::pair<double, double>>& blocked) {
    blocked.clear();
    const double reach = r + r_max;
    const CellRange xs = grid.x_range(x - reach, x + reach);
    const CellRange zs = grid.z_range(z - reach, z + reach);
    for (int l = grid.layer_of(from - reach); l < grid.layers(); ++l) {
        grid.for_each_in_layer(l, xs, zs, [&](const Sphere& s) {
            const double dx = x - s.x;
            const double dz = z - s.z;
            const double contact = r + s.r;
            const double h2 = dx * dx + dz * dz;
            if (h2 < contact * contact) {
                const double half = std::sqrt(contact * contact - h2);
                blocked.emplace_back(s.y - half, s.y + half);
            }
        });
    }
    std::sort(blocked.begin(), blocked.end());
    double y = from;
    for (const auto& [low, high] : blocked) {
        if (low >= y) {
            break;  // every later interval starts at or above y too
        }
        y = std::max(y, high);
    }
    return y;
}

}  // namespace sgmp::engine
