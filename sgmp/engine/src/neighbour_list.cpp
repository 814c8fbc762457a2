#include "sgmp/engine/neighbour_list.hpp"

#include <algorithm>

#include "sgmp/pack/cell_grid.hpp"

namespace sgmp::engine {

void NeighbourList::build(const std::vector<Ball>& s, double skin, const Container& sides) {
    const std::size_t n = s.size();
    offsets_.assign(n + 1, 0);
    neighbours_.clear();
    if (n == 0) {
        return;
    }
    double r_max = 0.0;
    centers_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        r_max = std::max(r_max, s[i].r);
        centers_[i] = Vec3(s[i].x, s[i].y, s[i].z);
    }
    // The vocabulary's pair search (nearest images when periodic), within the widest reach;
    // each pair is then kept at its own reach rᵢ + rⱼ + skin.
    const CellGrid grid(centers_, 2.0 * r_max + skin, NeighbourBox::of(sides));
    grid.for_each_pair([&](std::size_t i, std::size_t j, double distance2) {
        const double reach = s[i].r + s[j].r + skin;
        if (distance2 < reach * reach) {
            neighbours_.push_back(static_cast<std::uint32_t>(j));
            ++offsets_[i + 1];
        }
    });
    for (std::size_t i = 0; i < n; ++i) {
        offsets_[i + 1] += offsets_[i];
        std::sort(neighbours_.begin() + offsets_[i], neighbours_.begin() + offsets_[i + 1]);
    }
}

}  // namespace sgmp::engine
