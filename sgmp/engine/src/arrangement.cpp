#include "sgmp/engine/arrangement.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "sgmp/engine/settled_grid.hpp"
#include "sgmp/pack/color_bins.hpp"

namespace sgmp::engine {

namespace {

constexpr std::array<std::string_view, 4> kNames = {"single-column", "small-dense", "large-dense",
                                                    "loose-random"};

Particle make_particle(std::size_t index, const Vec3& center, double diameter, int color) {
    return Particle{static_cast<std::int64_t>(index + 1), center, 0.5 * diameter, color};
}

/// Centres 0.2 of the two diameters' mean apart (1.2·d apart for equal spheres).
std::vector<Particle> single_column(const std::vector<double>& d, const std::vector<int>& colors,
                                    const Container& box) {
    std::vector<Particle> out;
    out.reserve(d.size());
    double y = box.floor + 0.5 * d.front();
    for (std::size_t i = 0; i < d.size(); ++i) {
        if (i > 0) {
            y += 0.6 * (d[i - 1] + d[i]);
        }
        out.push_back(make_particle(i, Vec3(0.0, y, 0.0), d[i], colors[i]));
    }
    return out;
}

/// n × n layers with centres at lo + (i + ½)·width/n; layer L spans
/// [floor + L·d_max, floor + (L+1)·d_max) and its spheres rest on its bottom.
std::vector<Particle> layers(const std::vector<double>& d, double d_max, int n, double lo,
                             double width, const std::vector<int>& colors, const Container& box) {
    std::vector<Particle> out;
    out.reserve(d.size());
    const double spacing = width / n;
    const std::size_t per_layer = static_cast<std::size_t>(n) * n;
    for (std::size_t i = 0; i < d.size(); ++i) {
        const std::size_t layer = i / per_layer;
        const std::size_t in_layer = i % per_layer;
        const double x = lo + (static_cast<double>(in_layer % n) + 0.5) * spacing;
        const double z = lo + (static_cast<double>(in_layer / n) + 0.5) * spacing;
        const double y = box.floor + 0.5 * d[i] + d_max * static_cast<double>(layer);
        out.push_back(make_particle(i, Vec3(x, y, z), d[i], colors[i]));
    }
    return out;
}

std::vector<Particle> loose_random(const std::vector<double>& d, double d_max,
                                   const std::vector<int>& colors, const Container& box,
                                   Random& rng) {
    std::vector<Particle> out;
    out.reserve(d.size());
    // The level only rises, and a sphere more than d_max below it can never block a later
    // one, so the grid holds only a window of the cloud: when it grows past kWindowLayers
    // layers it is rebuilt from the spheres still within reach, its floor moved up. Memory
    // and time then stay proportional to N however tall the cloud gets.
    constexpr int kWindowLayers = 16;
    Container window = box;
    SettledGrid grid(window, d_max);
    std::vector<std::pair<double, double>> blocked;
    std::size_t window_first = 0;  // first particle that may still be in reach
    // The level is that of the sphere bottoms: the previous centre y_p and radius r_p give
    // the next start y_p − r_p + r (exactly y_p for equal sizes).
    double y_previous = box.floor + 0.5 * d.front();
    double r_previous = 0.5 * d.front();
    for (std::size_t i = 0; i < d.size(); ++i) {
        const double r = 0.5 * d[i];
        const double x = rng.uniform(box.x_min + r, box.x_max - r);
        const double z = rng.uniform(box.z_min + r, box.z_max - r);
        const double from = r == r_previous ? y_previous : y_previous - r_previous + r;
        const double y = lowest_free_height(grid, x, z, r, 0.5 * d_max, from, blocked);
        y_previous = y;
        r_previous = r;
        out.push_back(make_particle(i, Vec3(x, y, z), d[i], colors[i]));
        grid.insert(Sphere{x, y, z, r});
        if (grid.layers() > kWindowLayers) {
            window.floor = y - r - 2.0 * d_max;
            grid.reset(window);  // keeps the layers' memory
            while (window_first < out.size() &&
                   out[window_first].center.y() + out[window_first].radius < window.floor) {
                ++window_first;
            }
            for (std::size_t j = window_first; j < out.size(); ++j) {
                const Particle& p = out[j];
                if (p.center.y() + p.radius >= window.floor) {
                    grid.insert(Sphere{p.center.x(), p.center.y(), p.center.z(), p.radius});
                }
            }
        }
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
    return make_arrangement(arrangement, std::vector<double>(count, diameter), rng);
}

std::vector<Particle> make_arrangement(Arrangement arrangement,
                                       const std::vector<double>& diameters, Random& rng) {
    if (diameters.empty()) {
        return {};
    }
    const auto [d_min, d_max] = std::minmax_element(diameters.begin(), diameters.end());
    if (!(*d_min > 0.0) || !(*d_max < kContainerSide)) {
        throw std::invalid_argument("diameters must be in (0, 1.25)");
    }
    const Container box;
    const std::vector<int> colors = draw_colors(diameters.size(), rng);
    const int n = grid_columns(arrangement, *d_max);
    switch (arrangement) {
        case Arrangement::SingleColumn:
            return single_column(diameters, colors, box);
        case Arrangement::SmallDense:
            return layers(diameters, *d_max, n, -0.5 * kControlSide, kControlSide, colors, box);
        case Arrangement::LargeDense:
            return layers(diameters, *d_max, n, box.x_min, box.x_max - box.x_min, colors, box);
        case Arrangement::LooseRandom:
            return loose_random(diameters, *d_max, colors, box, rng);
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
