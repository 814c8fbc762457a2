#include "sgmp/pack/pack.hpp"

namespace sgmp {

double mean_diameter(const Pack& pack) {
    if (pack.particles.empty()) {
        return 0.0;
    }
    double sum = 0.0;
    for (const auto& particle : pack.particles) {
        sum += particle.radius;
    }
    return 2.0 * sum / static_cast<double>(pack.particles.size());
}

}  // namespace sgmp
