#include "sgmp/pack/text_precision.hpp"

#include <algorithm>
#include <cmath>

#include "sgmp/pack/pack_overlaps.hpp"

namespace sgmp {

PrecisionOverlaps precision_overlaps(const std::vector<Particle>& particles, int decimals,
                                     double floor) {
    PrecisionOverlaps result;
    result.bound = (std::sqrt(3.0) + 1.0) * std::pow(10.0, -decimals);
    for_each_overlap(
        particles, Container{},
        [&](std::size_t, std::size_t, double depth) {
            if (!(depth > floor)) {
                return;
            }
            ++result.overlaps;
            if (depth <= result.bound) {
                ++result.within_precision;
                result.max_overlap = std::max(result.max_overlap, depth);
            }
        },
        [](std::size_t, double) {});
    return result;
}

}  // namespace sgmp
