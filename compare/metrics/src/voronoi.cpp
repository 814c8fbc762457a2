#include "sgmp/compare/voronoi.hpp"

#include "sgmp/compare/pack_content_error.hpp"

#include <voro++/voro++.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

#include "sgmp/compare/parallel.hpp"

namespace sgmp::compare {
namespace {

/// voro++ finds neighbours by blocks; about 5–8 particles per block is its sweet spot.
constexpr double kParticlesPerBlock = 6.0;
/// Initial particle slots per block (voro++ doubles them when a block fills).
constexpr int kInitialBlockMemory = 8;
/// Threads split the measured cells, each with its own copy of the tessellation's container
/// (~60 bytes per particle): at most kMaxTasks copies, and only for ≥ kCellsPerTask cells each.
constexpr std::size_t kMaxTasks = 4;
constexpr std::size_t kCellsPerTask = 20000;

std::string text_of(const Vec3& v) {
    std::ostringstream out;
    out.precision(17);
    out << '(' << v.x() << ", " << v.y() << ", " << v.z() << ')';
    return out.str();
}

[[noreturn]] void reject(const std::string& what) {
    throw PackContentError("voronoi local phi: " + what);
}

void check_input(const std::vector<Particle>& particles, const Container& container,
                 const Box& region, const VoronoiOptions& options) {
    if (particles.empty()) {
        reject("no particles (a tessellation needs at least one centre)");
    }
    if (particles.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
        reject("too many particles (" + std::to_string(particles.size()) +
               "; voro++ numbers them with int)");
    }
    if (options.histogram_bins == 0) {
        reject("histogram_bins = 0 (must be at least 1)");
    }
    const bool finite = std::isfinite(container.x_min) && std::isfinite(container.x_max) &&
                        std::isfinite(container.z_min) && std::isfinite(container.z_max) &&
                        std::isfinite(container.floor);
    if (!finite || !(container.x_max > container.x_min) || !(container.z_max > container.z_min)) {
        reject("container '" + container.to_string() +
               "' is empty (needs finite x_min < x_max, z_min < z_max and floor)");
    }
    for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(region.lo[axis]) || !(region.hi[axis] > region.lo[axis])) {
            reject("region " + text_of(region.lo) + "–" + text_of(region.hi) +
                   " is empty (needs finite lo < hi on every axis; hi.y may be infinite)");
        }
    }
    for (const Particle& p : particles) {
        if (!std::isfinite(p.radius) || !(p.radius > 0.0)) {
            std::ostringstream out;
            out.precision(17);
            out << "particle " << p.id << " has radius " << p.radius
                << " (must be positive and finite)";
            reject(out.str());
        }
        const Vec3& c = p.center;
        if (!c.allFinite() ||
            !(c.x() > container.x_min && c.x() < container.x_max && c.z() > container.z_min &&
              c.z() < container.z_max && c.y() > container.floor)) {
            reject("particle " + std::to_string(p.id) + " has centre " + text_of(c) +
                   " outside container '" + container.to_string() +
                   "' (centres must lie strictly between the walls and above the floor)");
        }
    }
}

/// Indices of `particles` in a canonical order (x, y, z, r, id), so that the tessellation
/// sees the same sequence, and sums run in the same order, whatever the input order.
std::vector<int> canonical_order(const std::vector<Particle>& particles) {
    std::vector<int> order(particles.size());
    std::iota(order.begin(), order.end(), 0);
    const auto key = [&](int i) {
        const Particle& p = particles[static_cast<std::size_t>(i)];
        return std::make_tuple(p.center.x(), p.center.y(), p.center.z(), p.radius, p.id);
    };
    std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
    return order;
}

/// Blocks per axis for a box of sides `sides` holding `count` particles.
std::array<int, 3> block_grid(const Vec3& sides, std::size_t count) {
    const double block_side =
        std::cbrt(kParticlesPerBlock * sides.prod() / static_cast<double>(count));
    std::array<int, 3> blocks{};
    for (int axis = 0; axis < 3; ++axis) {
        const double n = std::round(sides[axis] / block_side);
        blocks[static_cast<std::size_t>(axis)] = static_cast<int>(std::clamp(n, 1.0, 1024.0));
    }
    return blocks;
}

/// One measured cell: φ_i, V_i, the sphere's volume, and whether the cell reaches the cap.
struct Cell {
    double phi = 0.0;
    double volume = 0.0;
    double sphere_volume = 0.0;
    bool at_cap = false;
    bool empty = false;
};

/// Tessellates with `VoroContainer` (voro::container or voro::container_poly) and fills
/// `cells[slot[k]]` for the origins k (indices into `sorted`) with slot[k] ≥ 0. The measured
/// origins are cut into `tasks` ranges of slots; each task builds its own, identical,
/// container, so a cell comes out with the same bits whichever task computes it.
template <class VoroContainer, class Put>
void tessellate(const std::vector<Particle>& particles, const std::vector<int>& sorted,
                const std::vector<int>& slot, const Box& bounds, std::size_t tasks, Put put,
                std::vector<Cell>& cells) {
    const Vec3 sides = bounds.hi - bounds.lo;
    const auto blocks = block_grid(sides, particles.size());
    const double cap = bounds.hi.y();
    const double cap_tolerance = 1e-9 * sides.maxCoeff();
    parallel_for(tasks, [&](std::size_t task) {
        const std::size_t first = task * cells.size() / tasks;
        const std::size_t last = (task + 1) * cells.size() / tasks;
        VoroContainer voro(bounds.lo.x(), bounds.hi.x(), bounds.lo.y(), bounds.hi.y(),
                           bounds.lo.z(), bounds.hi.z(), blocks[0], blocks[1], blocks[2], false,
                           false, false, kInitialBlockMemory);
        for (std::size_t k = 0; k < sorted.size(); ++k) {
            put(voro, static_cast<int>(k), particles[static_cast<std::size_t>(sorted[k])]);
        }
        if (static_cast<std::size_t>(voro.total_particles()) != sorted.size()) {
            reject("a centre lies on a container wall (the tessellation could not place it)");
        }
        voro::voronoicell cell;
        voro::c_loop_all loop(voro);
        if (!loop.start()) {
            return;
        }
        do {
            const int s = slot[static_cast<std::size_t>(loop.pid())];
            if (s < 0 || static_cast<std::size_t>(s) < first ||
                static_cast<std::size_t>(s) >= last) {
                continue;
            }
            Cell& out = cells[static_cast<std::size_t>(s)];
            if (!voro.compute_cell(cell, loop)) {
                out.empty = true;
                continue;
            }
            const double r = particles[static_cast<std::size_t>(sorted[loop.pid()])].radius;
            out.volume = cell.volume();
            out.sphere_volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
            out.phi = out.sphere_volume / out.volume;
            // voro++ stores the vertices relative to the centre, doubled.
            double top = -std::numeric_limits<double>::infinity();
            for (int v = 0; v < cell.p; ++v) {
                top = std::max(top, cell.pts[3 * v + 1]);
            }
            out.at_cap = loop.y() + 0.5 * top >= cap - cap_tolerance;
        } while (loop.inc());
    });
}

}  // namespace

VoronoiPhi voronoi_local_phi(const std::vector<Particle>& particles, const Container& container,
                             const Box& region, const VoronoiOptions& options) {
    check_input(particles, container, region, options);

    const std::vector<int> sorted = canonical_order(particles);
    // Summed in canonical order: the cap must not depend on the input order.
    double top = -std::numeric_limits<double>::infinity();
    double radius_sum = 0.0;
    bool equal_radii = true;
    for (const int i : sorted) {
        const Particle& p = particles[static_cast<std::size_t>(i)];
        top = std::max(top, p.center.y() + p.radius);
        radius_sum += p.radius;
        equal_radii = equal_radii && p.radius == particles.front().radius;
    }
    const double mean_diameter = 2.0 * radius_sum / static_cast<double>(particles.size());
    const Box bounds = container.box_up_to(top + mean_diameter);

    std::vector<int> slot(sorted.size(), -1);  // index among the measured origins
    std::int64_t count = 0;
    for (std::size_t k = 0; k < sorted.size(); ++k) {
        if (region.contains(particles[static_cast<std::size_t>(sorted[k])].center)) {
            slot[k] = static_cast<int>(count++);
        }
    }
    if (count == 0) {
        reject("region " + text_of(region.lo) + "–" + text_of(region.hi) + " holds no centre");
    }

    std::vector<Cell> cells(static_cast<std::size_t>(count));
    const std::size_t tasks = std::clamp<std::size_t>(
        std::min<std::size_t>(thread_count(), cells.size() / kCellsPerTask), 1, kMaxTasks);
    if (equal_radii) {
        tessellate<voro::container>(
            particles, sorted, slot, bounds, tasks,
            [](voro::container& voro, int k, const Particle& p) {
                voro.put(k, p.center.x(), p.center.y(), p.center.z());
            },
            cells);
    } else {
        tessellate<voro::container_poly>(
            particles, sorted, slot, bounds, tasks,
            [](voro::container_poly& voro, int k, const Particle& p) {
                voro.put(k, p.center.x(), p.center.y(), p.center.z(), p.radius);
            },
            cells);
    }
    for (std::size_t k = 0; k < sorted.size(); ++k) {
        if (slot[k] >= 0 && cells[static_cast<std::size_t>(slot[k])].empty) {
            const Particle& p = particles[static_cast<std::size_t>(sorted[k])];
            reject("particle " + std::to_string(p.id) + " at " + text_of(p.center) +
                   " has an empty cell (a sphere swallowed by a larger overlapping one)");
        }
    }

    VoronoiPhi result;
    result.cells = count;
    result.histogram.assign(options.histogram_bins, 0.0);
    const auto bins = static_cast<double>(options.histogram_bins);
    double phi_sum = 0.0;
    double sphere_volume = 0.0;
    for (const Cell& cell : cells) {
        phi_sum += cell.phi;
        result.cell_volume += cell.volume;
        sphere_volume += cell.sphere_volume;
        result.cap_cells += cell.at_cap ? 1 : 0;
        const double bin = std::clamp(std::floor(cell.phi * bins), 0.0, bins - 1.0);
        result.histogram[static_cast<std::size_t>(bin)] += 1.0;
    }
    const auto n = static_cast<double>(count);
    result.mean = phi_sum / n;
    double square_sum = 0.0;
    for (const Cell& cell : cells) {
        const double deviation = cell.phi - result.mean;
        square_sum += deviation * deviation;
    }
    result.sd = std::sqrt(square_sum / n);
    result.global = sphere_volume / result.cell_volume;
    for (double& h : result.histogram) {
        h *= bins / n;
    }
    return result;
}

}  // namespace sgmp::compare
