#include "sgmp/pack/random.hpp"

#include <limits>

namespace sgmp {

std::uint64_t Random::below(std::uint64_t n) {
    // Largest multiple of n that fits; draws at or above it are rejected.
    const std::uint64_t limit =
        std::numeric_limits<std::uint64_t>::max() - std::numeric_limits<std::uint64_t>::max() % n;
    std::uint64_t draw = engine_();
    while (draw >= limit) {
        draw = engine_();
    }
    return draw % n;
}

}  // namespace sgmp
