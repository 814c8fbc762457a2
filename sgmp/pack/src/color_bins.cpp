#include "sgmp/pack/color_bins.hpp"

#include <array>

namespace sgmp {

std::vector<int> draw_colors(std::size_t count, Random& rng) {
    std::array<std::size_t, kColorBins> left{};
    for (int k = 0; k < kColorBins; ++k) {
        left[k] = count / kColorBins + (static_cast<std::size_t>(k) < count % kColorBins ? 1 : 0);
    }
    std::vector<int> colors;
    colors.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        int non_empty = 0;
        for (const std::size_t n : left) {
            non_empty += n > 0 ? 1 : 0;
        }
        // The `pick`-th non-empty bin, counted from bin 0.
        auto pick = static_cast<int>(rng.below(static_cast<std::uint64_t>(non_empty)));
        for (int k = 0; k < kColorBins; ++k) {
            if (left[k] == 0) {
                continue;
            }
            if (pick-- == 0) {
                --left[k];
                colors.push_back(k);
                break;
            }
        }
    }
    return colors;
}

}  // namespace sgmp
