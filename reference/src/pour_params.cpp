#include "sgmp/reference/pour_params.hpp"

#include "sgmp/reference/launcher.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/random.hpp"

namespace sgmp::reference {
double PourParams::diameter() const {
    return diameter_for_count(count, phi_target);
}

double PourParams::cloud_top() const {
    // Centres of spheres wholly inside the cloud lie in a box narrower by d on every side,
    // so the cloud's solid fraction is counted over that box: N v = f (L - d)² (h - d).
    const double d = diameter();
    const double solid = static_cast<double>(count) * std::numbers::pi / 6.0 * d * d * d;
    const Container container;
    const double width = container.x_max - container.x_min - d;
    const double depth = container.z_max - container.z_min - d;
    return container.floor + d + solid / (cloud_fraction * width * depth);
}

std::uint64_t next_prime(std::uint64_t n) {
    const auto is_prime = [](std::uint64_t k) {
        if (k < 2) {
            return false;
        }
        for (std::uint64_t f = 2; f * f <= k; ++f) {
            if (k % f == 0) {
                return false;
            }
        }
        return true;
    };
    while (!is_prime(n)) {
        ++n;
    }
    return n;
}

LiggghtsSeeds liggghts_seeds(std::uint64_t seed) {
    Random random(seed);
    const auto draw = [&random] { return next_prime(10'007 + random.below(100'000'000)); };
    LiggghtsSeeds seeds;
    seeds.particle_template = draw();
    seeds.distribution = draw();
    seeds.insertion = draw();
    return seeds;
}

}  // namespace sgmp::reference
