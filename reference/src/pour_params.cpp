#include "sgmp/reference/pour_params.hpp"

#include "sgmp/reference/launcher.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/random.hpp"

namespace sgmp::reference {
std::vector<PourSpecies> PourParams::species() const {
    if (!is_blend()) {
        return {{diameter_for_count(count, phi_target), count, density}};
    }
    const std::vector<SizeMode> modes = number_fractions(size_modes, fraction_basis);
    const double scale = diameter_scale(count, phi_target, modes);
    const std::vector<std::size_t> counts = mode_counts(count, modes);
    std::vector<PourSpecies> result;
    for (std::size_t i = 0; i < modes.size(); ++i) {
        // Densities relative to species 1's (a species without one has species 1's).
        const double relative_density = modes[i].density.value_or(modes[0].density.value_or(1.0)) /
                                        modes[0].density.value_or(1.0);
        result.push_back(
            {modes[i].relative_diameter * scale, counts[i], density * relative_density});
    }
    return result;
}

double PourParams::diameter() const {
    if (!is_blend()) {
        return diameter_for_count(count, phi_target);
    }
    double sum = 0.0;
    for (const PourSpecies& s : species()) {
        sum += static_cast<double>(s.count) * s.diameter;
    }
    return sum / static_cast<double>(count);
}

double PourParams::largest_diameter() const {
    double largest = 0.0;
    for (const PourSpecies& s : species()) {
        largest = std::max(largest, s.diameter);
    }
    return largest;
}

Container PourParams::container() const {
    Container c;
    c.periodic = sides == Sides::Periodic;
    return c;
}

double PourParams::cloud_top() const {
    // Centres of spheres wholly inside the cloud lie in a box narrower by d on every side,
    // so the cloud's solid fraction is counted over that box: N v = f (L - d)² (h - d); for
    // a blend the box of the largest spheres' centres.
    double solid = 0.0;
    double largest = 0.0;
    for (const PourSpecies& s : species()) {
        solid += static_cast<double>(s.count) * std::numbers::pi / 6.0 * s.diameter * s.diameter *
                 s.diameter;
        largest = std::max(largest, s.diameter);
    }
    const double d = largest;
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

std::vector<LiggghtsSeeds> liggghts_species_seeds(std::uint64_t seed, std::size_t species) {
    Random random(seed);
    const auto draw = [&random] { return next_prime(10'007 + random.below(100'000'000)); };
    std::vector<LiggghtsSeeds> all(std::max<std::size_t>(species, 1));
    for (LiggghtsSeeds& seeds : all) {
        seeds.particle_template = draw();
        seeds.distribution = draw();
        seeds.insertion = draw();
    }
    return all;
}

LiggghtsSeeds liggghts_seeds(std::uint64_t seed) {
    return liggghts_species_seeds(seed, 1).front();
}

}  // namespace sgmp::reference
