#include "sgmp/metrics/voronoi.hpp"

#include "sgmp/metrics/pack_content_error.hpp"

#include <voro++/voro++.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

#include "sgmp/metrics/parallel.hpp"
#include "sgmp/pack/periodic_images.hpp"

namespace sgmp::metrics {
namespace {

/// voro++ finds neighbours by blocks; about 5–8 particles per block is its sweet spot.
constexpr double kParticlesPerBlock = 6.0;
/// Initial particle slots per block (voro++ doubles them when a block fills).
constexpr int kInitialBlockMemory = 8;
/// The halo of centres around a slab, in mean diameters (a cell needs every centre within
/// twice its largest vertex distance: about 1.5 d in a dense pack).
constexpr double kHaloDiameters = 3.0;

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
    if (options.cells_per_slab == 0) {
        reject("cells_per_slab = 0 (must be at least 1)");
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
        // With periodic sides a centre belongs in [x_min, x_max) × [z_min, z_max).
        const bool across = container.periodic
                                ? c.x() >= container.x_min && c.x() < container.x_max &&
                                      c.z() >= container.z_min && c.z() < container.z_max
                                : c.x() > container.x_min && c.x() < container.x_max &&
                                      c.z() > container.z_min && c.z() < container.z_max;
        if (!c.allFinite() || !(across && c.y() > container.floor)) {
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

/// Fills out from voro++'s cell of sorted position k, centre c, and returns the cell's
/// largest vertex distance from the centre, squared (voro++ stores vertices doubled).
double fill_cell(voro::voronoicell& cell, const Vec3& c, double radius, double cap,
                 double cap_tolerance, Cell& out) {
    out.volume = cell.volume();
    out.sphere_volume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
    out.phi = out.sphere_volume / out.volume;
    double top = -std::numeric_limits<double>::infinity();
    double reach = 0.0;
    for (int v = 0; v < cell.p; ++v) {
        const double* q = cell.pts + 3 * v;
        top = std::max(top, q[1]);
        reach = std::max(reach, 0.25 * (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]));
    }
    out.at_cap = c.y() + 0.5 * top >= cap - cap_tolerance;
    return reach;
}

/// Tessellates with `VoroContainer` (voro::container or voro::container_poly) and fills
/// `cells[slot[k]]` for the origins k (indices into `sorted`, which runs by increasing x)
/// with slot[k] ≥ 0.
///
/// Slabs: the measured origins are cut, in sorted order, into slabs of about cells_per_slab
/// (a number fixed by the input, never by the thread count); each slab is tessellated on
/// its own, in a container spanning the box of its measured centres widened by a halo of
/// kHaloDiameters mean diameters on each side (cut at the real walls), holding only the
/// centres in it.
/// A cell computed there is the cell of the whole pack when no centre it lacks could cut
/// it: with R its largest vertex distance, every centre within 2R is present, and no
/// artificial side lies within 2R (then none clipped the cell either). A cell that fails
/// the test is computed again in a container of every centre. Slabs run on the threads;
/// each cell comes from one fixed container, so results do not depend on the thread count.
///
/// Periodic sides (`periodic` holds the cell up to the lid, and entries of `particles` from
/// `originals` on are images): the bounds reach past the cell over the images and their
/// lateral sides are artificial too; a cell the slabs cannot vouch for is computed again in
/// voro++'s periodic container of the cell, holding the particles alone.
template <class VoroContainer, class Put>
void tessellate(const std::vector<Particle>& particles, const std::vector<int>& sorted,
                const std::vector<int>& slot, const Box& bounds, const std::optional<Box>& periodic,
                std::size_t originals, double mean_diameter, std::size_t cells_per_slab,
                unsigned threads, Put put, std::vector<Cell>& cells) {
    const bool open_sides = periodic.has_value();
    const double cap = bounds.hi.y();
    const double cap_tolerance = 1e-9 * (bounds.hi - bounds.lo).maxCoeff();
    const double halo = kHaloDiameters * mean_diameter;
    // Sorted positions of the measured origins, in slot order (sorted is x-major).
    std::vector<std::size_t> origin_at(cells.size());
    for (std::size_t k = 0; k < sorted.size(); ++k) {
        if (slot[k] >= 0) {
            origin_at[static_cast<std::size_t>(slot[k])] = k;
        }
    }
    const std::size_t slabs = std::max<std::size_t>(1, cells.size() / cells_per_slab);
    std::vector<std::vector<std::size_t>> redo(slabs);  // slots whose cell failed the test
    parallel_for(threads, slabs, [&](std::size_t s) {
        const std::size_t first = s * cells.size() / slabs;
        const std::size_t last = (s + 1) * cells.size() / slabs;
        if (first == last) {
            return;
        }
        // The box of the slab's measured centres widened by the halo, cut at the real walls;
        // its sides inside the container are open (artificial).
        Vec3 lo = particles[static_cast<std::size_t>(sorted[origin_at[first]])].center;
        Vec3 hi = lo;
        for (std::size_t sl = first; sl < last; ++sl) {
            const Vec3& c = particles[static_cast<std::size_t>(sorted[origin_at[sl]])].center;
            lo = lo.cwiseMin(c);
            hi = hi.cwiseMax(c);
        }
        lo = (lo.array() - halo).matrix().cwiseMax(bounds.lo);
        hi = (hi.array() + halo).matrix().cwiseMin(bounds.hi);
        std::array<bool, 3> open_lo{};
        std::array<bool, 3> open_hi{};
        for (int a = 0; a < 3; ++a) {
            const bool lateral = open_sides && a != 1;
            open_lo[static_cast<std::size_t>(a)] = lateral || lo[a] > bounds.lo[a];
            open_hi[static_cast<std::size_t>(a)] = lateral || hi[a] < bounds.hi[a];
        }
        // The centres strictly inside the box: within one range of the x-sorted positions.
        const auto x_below = [&](double x, bool strict) {
            return static_cast<std::size_t>(
                std::partition_point(sorted.begin(), sorted.end(),
                                     [&](int i) {
                                         const double v =
                                             particles[static_cast<std::size_t>(i)].center.x();
                                         return strict ? v < x : v <= x;
                                     }) -
                sorted.begin());
        };
        const std::size_t begin = x_below(lo.x(), false);
        const std::size_t end = x_below(hi.x(), true);
        const auto inside = [&](const Vec3& c) {
            return (!open_lo[1] || c.y() > lo.y()) && (!open_hi[1] || c.y() < hi.y()) &&
                   (!open_lo[2] || c.z() > lo.z()) && (!open_hi[2] || c.z() < hi.z());
        };
        std::size_t held = 0;
        for (std::size_t k = begin; k < end; ++k) {
            held += inside(particles[static_cast<std::size_t>(sorted[k])].center) ? 1 : 0;
        }
        const auto blocks = block_grid(hi - lo, std::max<std::size_t>(held, 1));
        VoroContainer voro(lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z(), blocks[0], blocks[1],
                           blocks[2], false, false, false, kInitialBlockMemory);
        for (std::size_t k = begin; k < end; ++k) {
            const Particle& p = particles[static_cast<std::size_t>(sorted[k])];
            if (inside(p.center)) {
                put(voro, static_cast<int>(k), p);
            }
        }
        if (static_cast<std::size_t>(voro.total_particles()) != held) {
            reject("a centre lies on a container wall (the tessellation could not place it)");
        }
        // Squared distance from c to the nearest open side of the box.
        const auto open_gap_squared = [&](const Vec3& c) {
            double gap = std::numeric_limits<double>::infinity();
            for (int a = 0; a < 3; ++a) {
                if (open_lo[static_cast<std::size_t>(a)]) {
                    gap = std::min(gap, c[a] - lo[a]);
                }
                if (open_hi[static_cast<std::size_t>(a)]) {
                    gap = std::min(gap, hi[a] - c[a]);
                }
            }
            return gap * gap;
        };
        voro::voronoicell cell;
        voro::c_loop_all loop(voro);
        if (!loop.start()) {
            return;
        }
        do {
            const auto k = static_cast<std::size_t>(loop.pid());
            const int sl = slot[k];
            if (sl < 0 || static_cast<std::size_t>(sl) < first ||
                static_cast<std::size_t>(sl) >= last) {
                continue;
            }
            Cell& out = cells[static_cast<std::size_t>(sl)];
            if (!voro.compute_cell(cell, loop)) {
                redo[s].push_back(static_cast<std::size_t>(sl));
                continue;
            }
            const Particle& p = particles[static_cast<std::size_t>(sorted[k])];
            const double reach = fill_cell(cell, p.center, p.radius, cap, cap_tolerance, out);
            const double need = 4.0 * reach * (1.0 + 1e-9);  // (2R)², widened for rounding
            if (open_gap_squared(p.center) <= need) {
                redo[s].push_back(static_cast<std::size_t>(sl));
            }
        } while (loop.inc());
    });
    std::vector<std::size_t> again;
    for (const auto& r : redo) {
        again.insert(again.end(), r.begin(), r.end());
    }
    if (again.empty()) {
        return;
    }
    // The cells a slab could not vouch for, in a container of every centre (periodic: of
    // every particle, in the periodic cell).
    const Box& whole = periodic ? *periodic : bounds;
    const auto blocks = block_grid(whole.hi - whole.lo, periodic ? originals : sorted.size());
    VoroContainer voro(whole.lo.x(), whole.hi.x(), whole.lo.y(), whole.hi.y(), whole.lo.z(),
                       whole.hi.z(), blocks[0], blocks[1], blocks[2], open_sides, false, open_sides,
                       kInitialBlockMemory);
    for (std::size_t k = 0; k < sorted.size(); ++k) {
        if (!periodic || static_cast<std::size_t>(sorted[k]) < originals) {
            put(voro, static_cast<int>(k), particles[static_cast<std::size_t>(sorted[k])]);
        }
    }
    std::vector<char> wanted(cells.size(), 0);
    for (const std::size_t sl : again) {
        wanted[sl] = 1;
    }
    voro::voronoicell cell;
    voro::c_loop_all loop(voro);
    if (!loop.start()) {
        return;
    }
    do {
        const int sl = slot[static_cast<std::size_t>(loop.pid())];
        if (sl < 0 || wanted[static_cast<std::size_t>(sl)] == 0) {
            continue;
        }
        Cell& out = cells[static_cast<std::size_t>(sl)];
        if (!voro.compute_cell(cell, loop)) {
            out.empty = true;
            continue;
        }
        const Particle& p = particles[static_cast<std::size_t>(sorted[loop.pid()])];
        fill_cell(cell, p.center, p.radius, cap, cap_tolerance, out);
    } while (loop.inc());
}

/// The cells' statistics per species (sums in slot order: fixed by the input).
std::vector<VoronoiSpecies> by_species(const std::vector<Particle>& particles,
                                       const std::vector<int>& sorted, const std::vector<int>& slot,
                                       const std::vector<Cell>& cells) {
    std::map<int, std::vector<std::size_t>> slots;  // species -> slots, increasing
    for (std::size_t k = 0; k < sorted.size(); ++k) {
        if (slot[k] >= 0) {
            slots[particles[static_cast<std::size_t>(sorted[k])].species].push_back(
                static_cast<std::size_t>(slot[k]));
        }
    }
    std::vector<VoronoiSpecies> result;
    for (auto& [species, list] : slots) {
        std::sort(list.begin(), list.end());
        VoronoiSpecies s;
        s.species = species;
        s.cells = static_cast<std::int64_t>(list.size());
        double phi_sum = 0.0;
        double sphere = 0.0;
        double volume = 0.0;
        for (const std::size_t sl : list) {
            phi_sum += cells[sl].phi;
            sphere += cells[sl].sphere_volume;
            volume += cells[sl].volume;
        }
        const auto n = static_cast<double>(list.size());
        s.mean = phi_sum / n;
        double square_sum = 0.0;
        for (const std::size_t sl : list) {
            square_sum += (cells[sl].phi - s.mean) * (cells[sl].phi - s.mean);
        }
        s.sd = std::sqrt(square_sum / n);
        s.global = sphere / volume;
        result.push_back(s);
    }
    return result;
}

}  // namespace

VoronoiPhi voronoi_local_phi(const std::vector<Particle>& input, const Container& container,
                             const Box& region, const VoronoiOptions& options) {
    check_input(input, container, region, options);
    // With periodic sides: the particles, then their images within the margin below of a
    // lateral face; the bounds reach that far past the cell, and only the particles are
    // origins.
    double largest = 0.0;
    double input_radius_sum = 0.0;
    for (const Particle& p : input) {
        largest = std::max(largest, p.radius);
        input_radius_sum += p.radius;
    }
    const double margin =
        std::min(2.0 * kHaloDiameters * 2.0 * input_radius_sum / static_cast<double>(input.size()) +
                     4.0 * largest,
                 std::min(container.x_max - container.x_min, container.z_max - container.z_min));
    const ImagedParticles imaged = with_periodic_images(input, container, margin);
    const std::vector<Particle>& particles = imaged.particles;

    const std::vector<int> sorted = canonical_order(particles);
    // Summed in canonical order: the cap must not depend on the input order.
    double top = -std::numeric_limits<double>::infinity();
    double radius_sum = 0.0;
    bool equal_radii = true;
    for (const int i : sorted) {
        const Particle& p = particles[static_cast<std::size_t>(i)];
        top = std::max(top, p.center.y() + p.radius);
        if (static_cast<std::size_t>(i) < imaged.originals) {
            radius_sum += p.radius;
        }
        equal_radii = equal_radii && p.radius == particles.front().radius;
    }
    const double mean_diameter = 2.0 * radius_sum / static_cast<double>(imaged.originals);
    Box bounds = container.box_up_to(top + mean_diameter);
    std::optional<Box> periodic;
    if (container.periodic) {
        periodic = bounds;
        bounds.lo.x() -= margin;
        bounds.hi.x() += margin;
        bounds.lo.z() -= margin;
        bounds.hi.z() += margin;
    }

    std::vector<int> slot(sorted.size(), -1);  // index among the measured origins
    std::int64_t count = 0;
    for (std::size_t k = 0; k < sorted.size(); ++k) {
        if (static_cast<std::size_t>(sorted[k]) < imaged.originals &&
            region.contains(particles[static_cast<std::size_t>(sorted[k])].center)) {
            slot[k] = static_cast<int>(count++);
        }
    }
    if (count == 0) {
        reject("region " + text_of(region.lo) + "–" + text_of(region.hi) + " holds no centre");
    }

    std::vector<Cell> cells(static_cast<std::size_t>(count));
    if (equal_radii) {
        tessellate<voro::container>(
            particles, sorted, slot, bounds, periodic, imaged.originals, mean_diameter,
            options.cells_per_slab, options.threads,
            [](voro::container& voro, int k, const Particle& p) {
                voro.put(k, p.center.x(), p.center.y(), p.center.z());
            },
            cells);
    } else {
        tessellate<voro::container_poly>(
            particles, sorted, slot, bounds, periodic, imaged.originals, mean_diameter,
            options.cells_per_slab, options.threads,
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
    if (has_species(particles)) {
        result.by_species = by_species(particles, sorted, slot, cells);
    }
    result.global = sphere_volume / result.cell_volume;
    if (options.keep_local) {
        result.local.assign(imaged.originals, std::numeric_limits<double>::quiet_NaN());
        for (std::size_t k = 0; k < sorted.size(); ++k) {
            if (slot[k] >= 0) {
                result.local[static_cast<std::size_t>(sorted[k])] =
                    cells[static_cast<std::size_t>(slot[k])].phi;
            }
        }
    }
    for (double& h : result.histogram) {
        h *= bins / n;
    }
    return result;
}

}  // namespace sgmp::metrics
