#include "sgmp/engine/arrangement.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "sgmp/engine/colour_bins.hpp"
#include "sgmp/engine/settled_grid.hpp"

namespace sgmp::engine {

namespace {

constexpr std::array<std::string_view, 4> kNames = {"single-column", "small-dense", "large-dense",
                                                    "loose-random"};

Particle make_particle(std::size_t index, const Vec3& center, double diameter, int colour) {
    return Particle{static_cast<std::int64_t>(index + 1), center, 0.5 * diameter, colour};
}

std::vector<Particle> single_column(std::size_t count, double d, const std::vector<int>& colours,
                                    const Container& box) {
    std::vector<Particle> out;
    out.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const double y = box.floor + 0.5 * d + 1.2 * d * static_cast<double>(i);
        out.push_back(make_particle(i, Vec3(0.0, y, 0.0), d, colours[i]));
    }
    return out;
}

/// n × n layers with centres at lo + (i + ½)·width/n, layers d apart from the floor up.
std::vector<Particle> layers(std::size_t count, double d, int n, double lo, double width,
                             const std::vector<int>& colours, const Container& box) {
    std::vector<Particle> out;
    out.reserve(count);
    const double spacing = width / n;
    const std::size_t per_layer = static_cast<std::size_t>(n) * n;
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t layer = i / per_layer;
        const std::size_t in_layer = i % per_layer;
        const double x = lo + (static_cast<double>(in_layer % n) + 0.5) * spacing;
        const double z = lo + (static_cast<double>(in_layer / n) + 0.5) * spacing;
        const double y = box.floor + 0.5 * d + d * static_cast<double>(layer);
        out.push_back(make_particle(i, Vec3(x, y, z), d, colours[i]));
    }
    return out;
}

std::vector<Particle> loose_random(std::size_t count, double d, const std::vector<int>& colours,
                                   const Container& box, Random& rng) {
    std::vector<Particle> out;
    out.reserve(count);
    const double r = 0.5 * d;
    SettledGrid grid(box, d);
    std::vector<std::pair<double, double>> blocked;
    double level = box.floor + r;
    for (std::size_t i = 0; i < count; ++i) {
        const double x = rng.uniform(box.x_min + r, box.x_max - r);
        const double z = rng.uniform(box.z_min + r, box.z_max - r);
        level = lowest_free_height(grid, x, z, r, r, level, blocked);
        out.push_back(make_particle(i, Vec3(x, level, z), d, colours[i]));
        grid.insert(Sphere{x, level, z, r});
    }
    return out;
}

}  // namespace

std::optional<Arrangement> parse_arrangement(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i) {
        if (name == kNames[i]) {
            return static_cast<Arrangement>(i);
        }
    }
    return std::nullopt;
}

std::string_view to_string(Arrangement arrangement) {
    return kNames.at(static_cast<std::size_t>(arrangement));
}

std::string_view arrangement_names() {
    return "single-column, small-dense, large-dense, loose-random";
}

int grid_columns(Arrangement arrangement, double diameter) {
    const auto columns = [&](double width) {
        return static_cast<int>(std::max(1.0, std::floor(width / diameter)));
    };
    switch (arrangement) {
        case Arrangement::SmallDense:
            return columns(kControlSide);
        case Arrangement::LargeDense:
            return columns(kContainerSide);
        case Arrangement::SingleColumn:
            return 1;
        case Arrangement::LooseRandom:
            return 0;
    }
    return 0;
}

std::vector<Particle> make_arrangement(Arrangement arrangement, std::size_t count, double diameter,
                                       Random& rng) {
    if (!(diameter > 0.0) || !(diameter < kContainerSide)) {
        throw std::invalid_argument("diameter " + std::to_string(diameter) +
                                    " must be in (0, 1.25)");
    }
    const Container box;
    const std::vector<int> colours = draw_colours(count, rng);
    const int n = grid_columns(arrangement, diameter);
    switch (arrangement) {
        case Arrangement::SingleColumn:
            return single_column(count, diameter, colours, box);
        case Arrangement::SmallDense:
            return layers(count, diameter, n, -0.5 * kControlSide, kControlSide, colours, box);
        case Arrangement::LargeDense:
            return layers(count, diameter, n, box.x_min, box.x_max - box.x_min, colours, box);
        case Arrangement::LooseRandom:
            return loose_random(count, diameter, colours, box, rng);
    }
    return {};
}

double starting_height(const std::vector<Particle>& particles, const Container& container) {
    double top = container.floor;
    for (const Particle& p : particles) {
        top = std::max(top, p.center.y() + p.radius);
    }
    return top - container.floor;
}

}  // namespace sgmp::engine
