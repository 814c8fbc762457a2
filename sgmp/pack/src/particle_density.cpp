#include "sgmp/pack/particle_density.hpp"

#include <algorithm>
#include <numbers>

#include "sgmp/pack/size_modes.hpp"

namespace sgmp {

std::optional<std::vector<double>> particle_densities(const Pack& pack) {
    if (const auto uniform = pack.metadata.get_number("particle_density")) {
        return std::vector<double>(pack.particles.size(), *uniform);
    }
    const auto text = pack.metadata.get("size_modes");
    if (!text) {
        return std::nullopt;
    }
    const auto modes = parse_size_modes(*text);
    if (!modes || modes->empty() ||
        std::any_of(modes->begin(), modes->end(), [](const SizeMode& m) { return !m.density; })) {
        return std::nullopt;
    }
    std::vector<double> densities;
    densities.reserve(pack.particles.size());
    for (const Particle& p : pack.particles) {
        const int species = std::max(p.species, 1);  // 0: equal spheres, the first mode
        if (static_cast<std::size_t>(species) > modes->size()) {
            return std::nullopt;
        }
        densities.push_back(*(*modes)[static_cast<std::size_t>(species - 1)].density);
    }
    return densities;
}

bool densities_vary(const std::vector<double>& densities) {
    return std::adjacent_find(densities.begin(), densities.end(), std::not_equal_to<>()) !=
           densities.end();
}

double sphere_mass(double density, double radius) {
    const double diameter = 2.0 * radius;
    return density * std::numbers::pi / 6.0 * diameter * diameter * diameter;
}

}  // namespace sgmp
