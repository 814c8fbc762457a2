#include "sgmp/compare/local_structure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "sgmp/compare/ball_cut.hpp"
#include "sgmp/compare/parallel.hpp"
#include "sgmp/compare/spatial_order.hpp"

namespace sgmp::compare {
namespace {

constexpr std::size_t kGroupSize = 32;      // origins per kd-tree query (radius 5·d)
constexpr std::size_t kGroupsPerChunk = 8;  // groups per parallel work item
constexpr std::size_t kMaxZ = 64;  // Z above this is recorded as kMaxZ (never seen in packs)

struct Partial {
    std::vector<std::int64_t> z_sum;
    std::vector<std::vector<std::int64_t>> z_histogram;
    std::vector<std::int64_t> wall_contacts;
    std::vector<std::int64_t> pairs;
    std::vector<double> shell_volume;
    std::int64_t full_shell_origins = 0;
    std::int64_t corrected_origins = 0;
    std::int64_t split_pairs[2] = {0, 0};
    double split_volume[2] = {0.0, 0.0};  // of corrected origins
    BondSums global;
    double q6_local_sum = 0.0;
    std::int64_t origins_with_bonds = 0;

    Partial(std::size_t tolerances, std::size_t bins)
        : z_sum(tolerances, 0),
          z_histogram(tolerances, std::vector<std::int64_t>(kMaxZ + 1, 0)),
          wall_contacts(tolerances, 0),
          pairs(bins, 0),
          shell_volume(bins, 0.0) {}

    void add(const Partial& o) {
        for (std::size_t t = 0; t < z_sum.size(); ++t) {
            z_sum[t] += o.z_sum[t];
            wall_contacts[t] += o.wall_contacts[t];
            for (std::size_t z = 0; z <= kMaxZ; ++z) {
                z_histogram[t][z] += o.z_histogram[t][z];
            }
        }
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            pairs[k] += o.pairs[k];
            shell_volume[k] += o.shell_volume[k];
        }
        full_shell_origins += o.full_shell_origins;
        corrected_origins += o.corrected_origins;
        for (int w = 0; w < 2; ++w) {
            split_pairs[w] += o.split_pairs[w];
            split_volume[w] += o.split_volume[w];
        }
        global.add(o.global);
        q6_local_sum += o.q6_local_sum;
        origins_with_bonds += o.origins_with_bonds;
    }
};

/// Gaps from the sphere to the four walls and the floor.
std::array<double, 5> wall_gaps(const Particle& p, const Container& c) {
    const Vec3& x = p.center;
    return {x.x() - c.x_min - p.radius, c.x_max - x.x() - p.radius, x.z() - c.z_min - p.radius,
            c.z_max - x.z() - p.radius, x.y() - c.floor - p.radius};
}

/// The split-ratio windows [centre ∓ half-width]·d, as absolute radii.
struct SplitWindows {
    double lo[2];
    double hi[2];
    bool inside_range;  // both windows lie within the g(r) range

    SplitWindows(double d, double outer) {
        const double centres[2] = {kSplitLow, kSplitHigh};
        for (int w = 0; w < 2; ++w) {
            lo[w] = (centres[w] - kSplitWindowHalfWidth) * d;
            hi[w] = (centres[w] + kSplitWindowHalfWidth) * d;
        }
        inside_range = hi[1] <= outer;
    }

    void count(double distance, std::int64_t* pairs) const {
        for (int w = 0; w < 2; ++w) {
            pairs[w] += (distance >= lo[w] && distance <= hi[w]) ? 1 : 0;
        }
    }

    void add_volumes(const Vec3& center, const Box& space, double* volume) const {
        for (int w = 0; w < 2; ++w) {
            volume[w] +=
                ball_box_volume(center, hi[w], space) - ball_box_volume(center, lo[w], space);
        }
    }

    [[nodiscard]] double full_volume(int w) const {
        return (4.0 * std::numbers::pi / 3.0) * (hi[w] * hi[w] * hi[w] - lo[w] * lo[w] * lo[w]);
    }
};

}  // namespace

LocalStructure measure_local_structure(const std::vector<Particle>& particles,
                                       const NeighbourIndex& index,
                                       const std::vector<Index>& origins,
                                       const LocalStructureOptions& options) {
    const std::size_t tolerances = options.tolerances.size();
    const double d = options.mean_diameter;
    const double width = options.bin_width_over_d * d;
    const double outer = bin_outer(options.bins - 1, width);
    const SplitWindows split(d, outer);
    // Bins that can hold a distance of the split windows (a cheap test before the exact one).
    const std::size_t split_first_bin = bin_of(split.lo[0], 1.0 / width) - 1;
    const std::size_t split_bins = bin_of(split.hi[1], 1.0 / width) + 1 - split_first_bin;
    double max_radius = 0.0;
    for (const Particle& p : particles) {
        max_radius = std::max(max_radius, p.radius);
    }
    const double max_tolerance =
        tolerances == 0 ? 0.0
                        : *std::max_element(options.tolerances.begin(), options.tolerances.end());
    std::vector<double> thresholds(tolerances);
    for (std::size_t t = 0; t < tolerances; ++t) {
        thresholds[t] = options.tolerances[t] * d;
    }
    const double max_threshold = max_tolerance * d;

    const double reach = std::max(
        {outer, 2.0 * max_radius + max_tolerance * d, options.q6_cutoff * 2.0 * max_radius});
    const double reach_squared = reach * reach;
    const double per_width = 1.0 / width;
    const std::vector<Index> ordered = spatial_order(particles, origins, d);
    const std::vector<QueryGroup> groups = query_groups(particles, ordered, kGroupSize);

    const Partial total = chunked_reduce(
        groups.size(), kGroupsPerChunk, Partial(tolerances, options.bins),
        [&](Partial& part, std::size_t begin, std::size_t end) {
            Candidates candidates;
            std::vector<double> squared;
            std::vector<Index> near;
            std::vector<int> z(tolerances);
            for (std::size_t g = begin; g < end; ++g) {
                candidates.gather(index, particles, groups[g], reach);
                const std::size_t n = candidates.index.size();
                squared.resize(n);
                near.resize(n);
                for (std::size_t o = groups[g].begin; o < groups[g].end; ++o) {
                    const Index i = ordered[o];
                    const Particle& a = particles[i];
                    const double ax = a.center.x();
                    const double ay = a.center.y();
                    const double az = a.center.z();
                    // Distances to every candidate, then a branch-free list of those
                    // within reach (about a third: a branch here would mispredict often).
                    std::size_t m = 0;
                    for (std::size_t k = 0; k < n; ++k) {
                        const double dx = candidates.x[k] - ax;
                        const double dy = candidates.y[k] - ay;
                        const double dz = candidates.z[k] - az;
                        squared[k] = dx * dx + dy * dy + dz * dz;
                    }
                    for (std::size_t k = 0; k < n; ++k) {
                        near[m] = static_cast<Index>(k);
                        const bool within = squared[k] <= reach_squared;
                        const bool other = candidates.index[k] != i;
                        m += static_cast<std::size_t>(within & other);
                    }
                    std::fill(z.begin(), z.end(), 0);
                    BondSums bonds;
                    for (std::size_t q = 0; q < m; ++q) {
                        const std::size_t k = near[q];
                        const double distance = std::sqrt(squared[k]);
                        const auto bin = bin_of(distance, per_width);
                        if (bin < options.bins) {
                            ++part.pairs[bin];
                        }
                        if (bin - split_first_bin <= split_bins) {  // unsigned: one compare
                            split.count(distance, part.split_pairs);
                        }
                        const double rb = candidates.r[k];
                        const double gap = distance - a.radius - rb;
                        if (gap <= max_threshold) {
                            for (std::size_t t = 0; t < tolerances; ++t) {
                                z[t] += gap <= thresholds[t] ? 1 : 0;
                            }
                        }
                        if (distance <= options.q6_cutoff * (a.radius + rb) && distance > 0.0) {
                            const Vec3 bond(candidates.x[k] - ax, candidates.y[k] - ay,
                                            candidates.z[k] - az);
                            bonds.add(bond / distance);
                        }
                    }
                    const auto walls = wall_gaps(a, options.container);
                    for (std::size_t t = 0; t < tolerances; ++t) {
                        part.z_sum[t] += z[t];
                        ++part.z_histogram[t][std::min<std::size_t>(z[t], kMaxZ)];
                        for (const double gap : walls) {
                            part.wall_contacts[t] += gap <= thresholds[t] ? 1 : 0;
                        }
                    }
                    if (shells_inside(a.center, outer, options.space)) {
                        ++part.full_shell_origins;
                    } else {
                        ++part.corrected_origins;
                        add_shell_volumes(a.center, width, options.bins, options.space,
                                          part.shell_volume);
                        if (split.inside_range) {
                            split.add_volumes(a.center, options.space, part.split_volume);
                        }
                    }
                    if (bonds.bonds > 0) {
                        part.global.add(bonds);
                        part.q6_local_sum += bonds.q6();
                        ++part.origins_with_bonds;
                    }
                }
            }
        },
        [](Partial& sum, const Partial& part) { sum.add(part); });

    LocalStructure result;
    const auto n = static_cast<std::int64_t>(origins.size());
    Coordination& c = result.coordination;
    c.tolerances = options.tolerances;
    c.origins = n;
    c.wall_contacts = total.wall_contacts;
    for (std::size_t t = 0; t < tolerances; ++t) {
        c.z_mean.push_back(n > 0 ? static_cast<double>(total.z_sum[t]) / static_cast<double>(n)
                                 : 0.0);
        std::size_t top = 0;
        for (std::size_t zz = 0; zz <= kMaxZ; ++zz) {
            if (total.z_histogram[t][zz] > 0) {
                top = zz;
            }
        }
        std::vector<double> p(top + 1);
        for (std::size_t zz = 0; zz <= top; ++zz) {
            p[zz] = n > 0 ? static_cast<double>(total.z_histogram[t][zz]) / static_cast<double>(n)
                          : 0.0;
        }
        c.p_z.push_back(std::move(p));
    }

    Rdf& rdf = result.rdf;
    rdf.bin_width_over_d = options.bin_width_over_d;
    rdf.pairs = total.pairs;
    rdf.shell_volume = total.shell_volume;
    const auto full = static_cast<double>(total.full_shell_origins);
    for (std::size_t k = 0; k < options.bins; ++k) {
        const double r0 = bin_inner(k, width);
        const double r1 = bin_outer(k, width);
        rdf.shell_volume[k] +=
            full * (4.0 * std::numbers::pi / 3.0) * (r1 * r1 * r1 - r0 * r0 * r0);
    }
    rdf.origins = n;
    rdf.corrected_origins = total.corrected_origins;
    rdf.space = options.space;
    rdf.density_rule = options.density_rule;
    rdf.space_density = static_cast<double>(particles.size()) / options.space.volume();
    if (split.inside_range) {
        for (int w = 0; w < 2; ++w) {
            rdf.split_pairs[w] = total.split_pairs[w];
            rdf.split_volume[w] = total.split_volume[w] + full * split.full_volume(w);
        }
    }
    normalise(rdf);

    BondOrder& q = result.bond_order;
    q.cutoff = options.q6_cutoff;
    q.q6_global = total.global.q6();
    q.origins_with_bonds = total.origins_with_bonds;
    q.q6_local_mean = total.origins_with_bonds > 0
                          ? total.q6_local_sum / static_cast<double>(total.origins_with_bonds)
                          : 0.0;
    return result;
}

}  // namespace sgmp::compare
