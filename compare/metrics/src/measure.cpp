#include "sgmp/metrics/measure.hpp"

#include "sgmp/metrics/pack_content_error.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <stdexcept>
#include <thread>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "sgmp/metrics/parallel.hpp"
#include "sgmp/metrics/spatial_order.hpp"
#include "sgmp/pack/crowding.hpp"
#include "sgmp/pack/pack_extent.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/periodic_images.hpp"

namespace sgmp::metrics {
namespace {

thread_local StageTimes stage_times;

class Stopwatch {
  public:
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - start_).count();
        start_ = now;
        return seconds;
    }

  private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// Returns the heap's free memory to the system (glibc): reading a pack leaves tens of
/// bytes per particle of freed small blocks, which the large arrays made below (mapped
/// apart from the heap) cannot reuse; without this they count in the peak resident size.
void release_free_heap() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

std::string describe(const Box& b) {
    return format_number(b.lo.x()) + " " + format_number(b.hi.x()) + " " + format_number(b.lo.y()) +
           " " + format_number(b.hi.y()) + " " + format_number(b.lo.z()) + " " +
           format_number(b.hi.z());
}

void check_region(const Box& region, const Container& container) {
    if (!((region.hi - region.lo).array() > 0.0).all() || !region.lo.allFinite() ||
        !region.hi.allFinite()) {
        throw ParameterError("region", "'" + describe(region) + "'",
                             "must be finite with xlo < xhi, ylo < yhi, zlo < zhi");
    }
    if (region.lo.x() < container.x_min || region.hi.x() > container.x_max ||
        region.lo.z() < container.z_min || region.hi.z() > container.z_max ||
        region.lo.y() < container.floor) {
        throw ParameterError("region", "'" + describe(region) + "'",
                             "must lie inside the container '" + container.to_string() +
                                 "' (x_min x_max z_min z_max floor)");
    }
}

/// The control volume, in the file's unit when it was written with a length scale
/// (output_frame.hpp: `length_scale` is one control-volume side). With periodic sides
/// there is no lateral wall to keep away from: the whole cell across, the control
/// volume's heights.
Box default_region(const Pack& pack, const Container& container) {
    Box region = control_volume();
    if (const auto scale = pack.metadata.get_number("length_scale"); scale && *scale > 0.0) {
        region.lo *= *scale;
        region.hi *= *scale;
    }
    if (container.periodic) {
        region.lo.x() = container.x_min;
        region.hi.x() = container.x_max;
        region.lo.z() = container.z_min;
        region.hi.z() = container.z_max;
    }
    return region;
}

/// How far from a centre the pair passes look: the g(r) range (and the half bin a pair
/// type's bins may be shifted by), Q6's bonds and the widest contact tolerance.
double pair_reach(const MeasureOptions& o, double d, double max_radius) {
    double widest = 0.0;
    for (const double t : coordination_tolerances()) {
        widest = std::max(widest, t);
    }
    return std::max({(o.gr_range + 1.5 * o.gr_bin_width) * d, o.q6_cutoff * 2.0 * max_radius,
                     2.0 * max_radius + widest * d});
}

/// The pack with periodic sides as the pair passes see it: the particles, then their
/// images within `reach` of a lateral face (periodic_images.hpp; several periods away when
/// the reach is wider than the cell, as for a small pack's g(r) range).
std::vector<Particle> with_images(const std::vector<Particle>& particles,
                                  const Container& container, double reach) {
    return with_periodic_images(particles, container, reach).particles;
}

/// The centres' space of g(r) with periodic sides: unbounded across (the images fill the
/// reach beyond each face), so no shell is cut but by the floor and the top.
Box widened(Box space, const Container& container, double reach) {
    if (container.periodic) {
        space.lo.x() = container.x_min - reach;
        space.hi.x() = container.x_max + reach;
        space.lo.z() = container.z_min - reach;
        space.hi.z() = container.z_max + reach;
    }
    return space;
}

}  // namespace

/// Most phi(y) slabs one measurement makes.
constexpr double kMaxSlabs = 1e6;

void validate(const MeasureOptions& o) {
    const auto positive = [](double v, const char* name) {
        if (!(v > 0.0) || !std::isfinite(v)) {
            throw ParameterError(name, format_number(v), "must be a positive number");
        }
    };
    positive(o.slab_thickness, "slab");
    positive(o.gr_bin_width, "gr_bin");
    positive(o.gr_range, "gr_range");
    positive(o.q6_cutoff, "q6_cutoff");
    if (!(o.overlap_floor >= 0.0) || !std::isfinite(o.overlap_floor)) {
        throw ParameterError("overlap_floor", format_number(o.overlap_floor),
                             "must be a non-negative number");
    }
    if (o.gr_bin_width > o.gr_range) {
        throw ParameterError("gr_bin", format_number(o.gr_bin_width),
                             "must not exceed --gr-range " + format_number(o.gr_range));
    }
    if (o.gr_range / o.gr_bin_width > 1e5) {
        throw ParameterError("gr_bin", format_number(o.gr_bin_width),
                             "--gr-range / --gr-bin must be at most 100000 bins");
    }
    // Bounds that keep memory finite: slabs are counted below, bonds grow as the cube.
    if (o.slab_thickness < 1e-3 || o.slab_thickness > 1e6) {
        throw ParameterError("slab", format_number(o.slab_thickness),
                             "must be at least 0.001 d and at most 1e6 d");
    }
    if (o.gr_range > 100.0) {
        throw ParameterError("gr_range", format_number(o.gr_range), "must be at most 100 d");
    }
    if (o.q6_cutoff > 10.0) {
        throw ParameterError("q6_cutoff", format_number(o.q6_cutoff), "must be at most 10");
    }
}

Container container_of(const Pack& pack, std::string* source) {
    if (source != nullptr) {
        // Where the walls came from (sgmp/pack/stated_container.hpp): the header, a
        // statement (--container, a manifest row) or a file box its spheres reach.
        const auto from = pack.metadata.get("container_from");
        *source = !pack.metadata.get("container") ? "thesis default" : from ? *from : "metadata";
    }
    if (pack.metadata.contains("periodic_y")) {
        throw std::invalid_argument(
            "the pack is periodic in y too (periodic_y): it has no floor, and the metrics "
            "measure a bed on one");
    }
    return sgmp::container_of(pack);
}

/// The particles sorted along a Morton curve of cells of side d, so that particles near in
/// space are near in memory (every pass then walks its grids and the arrays in cache).
std::vector<Particle> spatially_ordered(const std::vector<Particle>& particles, double d,
                                        unsigned threads) {
    std::vector<Index> all(particles.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        all[i] = static_cast<Index>(i);
    }
    // The copy's memory is mapped and zeroed (page faults: ~20 ms at 10⁶ particles) on a
    // second thread while the order is sorted, when there is one to spare.
    std::vector<Particle> ordered;
    const auto allocate = [&] { ordered.resize(particles.size()); };
    std::vector<Index> order;
    if (resolved_threads(threads) > 1) {
        std::exception_ptr failure;
        std::thread allocation([&] {
            try {
                allocate();
            } catch (...) {
                failure = std::current_exception();
            }
        });
        try {
            order = spatial_order(particles, std::move(all), d, threads);
        } catch (...) {
            allocation.join();
            throw;
        }
        allocation.join();
        if (failure) {
            std::rethrow_exception(failure);
        }
    } else {
        order = spatial_order(particles, std::move(all), d, threads);
        allocate();
    }
    constexpr std::size_t kChunk = 65536;
    parallel_for(threads, (order.size() + kChunk - 1) / kChunk, [&](std::size_t chunk) {
        const std::size_t end = std::min(order.size(), (chunk + 1) * kChunk);
        for (std::size_t k = chunk * kChunk; k < end; ++k) {
            ordered[k] = particles[order[k]];
        }
    });
    return ordered;
}

namespace {

/// The pack's sizes, container, region and top (Measurement's first fields), checked: a
/// positive finite mean diameter, at most kMaxSlabs slabs.
void describe_pack(const Pack& pack, const MeasureOptions& options, Measurement& m) {
    const auto& input = pack.particles;
    m.count = input.size();
    m.mean_diameter = mean_diameter(pack);
    const auto [lo, hi] = std::minmax_element(
        input.begin(), input.end(),
        [](const Particle& a, const Particle& b) { return a.radius < b.radius; });
    m.min_radius = lo->radius;
    m.max_radius = hi->radius;
    m.polydisperse = m.min_radius != m.max_radius;
    m.container = container_of(pack, &m.container_source);
    m.region = options.region.value_or(default_region(pack, m.container));
    check_region(m.region, m.container);
    m.top = -std::numeric_limits<double>::infinity();
    for (const Particle& p : input) {
        m.top = std::max(m.top, p.center.y() + p.radius);
    }
    const double d = m.mean_diameter;
    if (!(d > 0.0) || !std::isfinite(d)) {
        throw PackContentError("the pack's mean diameter must be positive and finite");
    }
    const double slabs =
        (std::max(m.top, m.region.hi.y()) - m.container.floor) / (options.slab_thickness * d);
    if (!(slabs <= kMaxSlabs)) {
        throw ParameterError("slab", format_number(options.slab_thickness),
                             "gives " + format_number(std::ceil(slabs)) +
                                 " slabs from the floor to the top sphere; at most " +
                                 std::to_string(static_cast<long>(kMaxSlabs)) + " are allowed");
    }
}

/// Before any pair search: spheres clumped past the hard-sphere limit (crowding.hpp) would
/// make every pair pass O(N²), and their metrics mean nothing.
void refuse_crowding(const std::vector<Particle>& input) {
    const auto crowded = overcrowded_cube(input);
    if (!crowded) {
        return;
    }
    const Particle& p = input[crowded->index];
    throw PackContentError(
        "sphere id " + std::to_string(p.id) + " at (" + format_number(p.center.x()) + ", " +
        format_number(p.center.y()) + ", " + format_number(p.center.z()) +
        "): " + std::to_string(crowded->centres) +
        " sphere centres in one cube of side 2*r_min = " + format_number(crowded->cube_side) +
        " with it; at most " + std::to_string(kMaxCentresPerCube) +
        " fit unless spheres overlap by more than the smallest radius, which makes the "
        "pair metrics meaningless");
}

/// The indices of the particles whose centres lie in the region (the origins of every
/// per-sphere mean); refused when there is none.
std::vector<Index> origins_in(const std::vector<Particle>& particles, const Box& region) {
    std::vector<Index> origins;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        if (region.contains(particles[i].center)) {
            origins.push_back(static_cast<Index>(i));
        }
    }
    if (origins.empty()) {
        throw ParameterError("region", "'" + describe(region) + "'", "holds no particle centre");
    }
    return origins;
}

/// φ(y) of the whole pack, and of each species when the pack has species.
void measure_phi_profiles(const std::vector<Particle>& field, bool species,
                          const MeasureOptions& options, Measurement& m) {
    const double top = std::max(m.top, m.region.hi.y());
    const double slab = options.slab_thickness * m.mean_diameter;
    m.phi_profile =
        packing_fraction_profile(field, m.region, m.container.floor, top, slab, options.threads);
    if (!species) {
        return;
    }
    std::map<int, std::vector<Particle>> of_species;
    for (const Particle& p : field) {
        of_species[p.species].push_back(p);
    }
    for (const auto& [id, members] : of_species) {
        m.phi_profile_by_species.push_back(
            {id, packing_fraction_profile(members, m.region, m.container.floor, top, slab,
                                          options.threads)
                     .phi});
    }
}

/// The pair passes' options: the tolerances, g(r)'s bins and density, Q6's cutoff and the
/// space the origins' density is taken over.
LocalStructureOptions local_options(const std::vector<Particle>& particles,
                                    const MeasureOptions& options, const Measurement& m,
                                    double reach) {
    const double d = m.mean_diameter;
    LocalStructureOptions local;
    local.tolerances = coordination_tolerances();
    local.mean_diameter = d;
    local.bin_width_over_d = options.gr_bin_width;
    local.bins = bins_for(options.gr_range / options.gr_bin_width);
    local.density_rule = options.gr_density;
    local.q6_cutoff = options.q6_cutoff;
    local.space =
        widened(options.gr_container_space ? container_space(particles, m.container)
                                           : center_space(particles, m.container, 0.5 * d),
                m.container, reach);
    local.container = m.container;
    local.threads = options.threads;
    return local;
}

/// The per-species options of the same passes.
SpeciesStructureOptions species_options(const LocalStructureOptions& local, const Box& region,
                                        std::size_t originals, unsigned threads) {
    SpeciesStructureOptions per_species;
    per_species.region = region;
    per_species.space = local.space;
    per_species.mean_diameter = local.mean_diameter;
    per_species.bin_width_over_d = local.bin_width_over_d;
    per_species.bins = local.bins;
    per_species.density_rule = local.density_rule;
    per_species.tolerances = local.tolerances;
    per_species.originals = originals;
    per_species.threads = threads;
    return per_species;
}

}  // namespace

Measurement measure(const Pack& pack, const MeasureOptions& options) {
    validate(options);
    if (pack.particles.empty()) {
        throw PackContentError("the pack has no particles");
    }
    release_free_heap();
    Stopwatch watch;
    Measurement m;
    describe_pack(pack, options, m);
    const double d = m.mean_diameter;
    refuse_crowding(pack.particles);
    std::vector<Particle> particles = spatially_ordered(pack.particles, d, options.threads);
    for (Particle& p : particles) {  // a foreign file's centres may lie a period out
        p.center = m.container.wrapped(p.center);
    }
    // With periodic sides every pass but the overlaps' (which images on its own) and the
    // tessellation's (likewise) runs over the particles and their images; origins are the
    // particles alone.
    const double reach = pair_reach(options, d, m.max_radius);
    std::vector<Particle> imaged;
    if (m.container.periodic) {
        imaged = with_images(particles, m.container, reach);
    }
    const std::vector<Particle>& field = m.container.periodic ? imaged : particles;
    const std::vector<Index> origins = origins_in(particles, m.region);
    stage_times.index = watch.lap();

    m.phi = packing_fraction(field, m.region);
    stage_times.phi = watch.lap();
    measure_phi_profiles(field, has_species(particles), options, m);
    stage_times.phi_profile = watch.lap();
    m.overlaps = measure_overlaps(particles, m.container, d, options.overlap_floor,
                                  options.worst_count, options.threads);
    stage_times.overlaps = watch.lap();

    const LocalStructureOptions local = local_options(particles, options, m, reach);
    m.local = measure_local_structure(field, origins, local);
    if (options.gr_thesis) {
        m.thesis_rdf = thesis_rdf(field, m.region, m.phi, options.gr_bin_width * d, local.bins);
    }
    stage_times.local = watch.lap();
    m.species = measure_species_structure(
        field, species_options(local, m.region, particles.size(), options.threads));
    stage_times.species = watch.lap();
    if (options.voronoi) {
        VoronoiOptions voronoi;
        voronoi.threads = options.threads;
        m.voronoi = voronoi_local_phi(particles, m.container, m.region, voronoi);
    }
    stage_times.voronoi = watch.lap();
    m.mixing = mixing_profile(particles, m.container.floor);
    if (m.polydisperse) {
        m.size_moments = size_moments(particles);
    }
    return m;
}

const StageTimes& last_stage_times() {
    return stage_times;
}

}  // namespace sgmp::metrics
