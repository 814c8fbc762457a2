#include "sgmp/reference/colours.hpp"

#include <array>
#include <cstddef>

namespace sgmp::reference {

void assign_colours(std::vector<Particle>& particles, Random& random) {
    const std::size_t n = particles.size();
    std::array<std::size_t, kColourBins> left{};
    for (std::size_t b = 0; b < left.size(); ++b) {
        left[b] = n / kColourBins + (b < n % kColourBins ? 1 : 0);
    }
    for (auto& particle : particles) {
        std::array<int, kColourBins> open{};
        std::size_t count = 0;
        for (int b = 0; b < kColourBins; ++b) {
            if (left[static_cast<std::size_t>(b)] > 0) {
                open[count++] = b;
            }
        }
        const int bin = open[random.below(count)];
        --left[static_cast<std::size_t>(bin)];
        particle.color = bin;
    }
}

}  // namespace sgmp::reference
