// Over 500 lines with reason: the one pair pass behind Z(δ), g(r), the split ratio and Q6
// (docs/pair-passes.md); its setup, per-column sums and finishing share private types.
#include "sgmp/metrics/local_structure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "sgmp/metrics/pair_columns.hpp"
#include "sgmp/metrics/pair_kernels.hpp"
#include "sgmp/metrics/parallel.hpp"
#include "sgmp/pack/size_classes.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"

namespace sgmp::metrics {
namespace {

// Columns of the origins' grid per parallel work item (~400 origins at 10^6 particles).
// Fixed (never from the thread count), and with it the order of every floating-point sum.
constexpr std::size_t kColumnsPerChunk = 64;
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

/// Gaps from the sphere to the four walls and the floor (with periodic sides, the floor
/// alone: the lateral gaps are infinite).
std::array<double, 5> wall_gaps(const Particle& p, const Container& c) {
    const Vec3& x = p.center;
    const double floor_gap = x.y() - c.floor - p.radius;
    if (c.periodic) {
        constexpr double kNone = std::numeric_limits<double>::infinity();
        return {kNone, kNone, kNone, kNone, floor_gap};
    }
    return {x.x() - c.x_min - p.radius, c.x_max - x.x() - p.radius, x.z() - c.z_min - p.radius,
            c.z_max - x.z() - p.radius, floor_gap};
}

/// The split-ratio windows [centre ∓ half-width]·d, as absolute radii.
struct SplitWindows {
    double lo[2];
    double hi[2];
    bool inside_range;  // both windows lie within the g(r) range

    SplitWindows(double d, double outer) {
        const double centers[2] = {kSplitLow, kSplitHigh};
        for (int w = 0; w < 2; ++w) {
            lo[w] = (centers[w] - kSplitWindowHalfWidth) * d;
            hi[w] = (centers[w] + kSplitWindowHalfWidth) * d;
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
                sphere_box_volume(center, hi[w], space, SphereBoxQuadrature::GaussLegendre) -
                sphere_box_volume(center, lo[w], space, SphereBoxQuadrature::GaussLegendre);
        }
    }

    [[nodiscard]] double full_volume(int w) const {
        return (4.0 * std::numbers::pi / 3.0) * (hi[w] * hi[w] * hi[w] - lo[w] * lo[w] * lo[w]);
    }
};

/// Everything one measurement derives from its options, fixed before the pass.
struct Setup {
    std::size_t tolerances;
    std::size_t bins;
    double width;
    double per_width;
    double outer;  // of the last g(r) bin
    SplitWindows split;
    std::size_t split_first_bin;  // bins that can hold a split-window distance: a cheap
    std::size_t split_bins;       // test before the exact one
    std::vector<double> thresholds;
    double max_threshold;
    double q6_cutoff;
    double reach;          // of the pair-counting pass: the g(r) range
    double reach_squared;  //
    double close_squared;  // a pair farther than this is neither a contact nor a bond
    BinSetup kernel;       // of count_bins
    bool equal;            // every radius is `radius`
    double radius;
    /// A wide blend (size_classes.hpp) gathers contacts and bonds from its small spheres
    /// and its large ones apart, each within its own reach (close_for).
    bool split_sizes = false;
    double small_radius = 0.0;  // the largest small radius when split_sizes
    double q6_factor = 0.0;     // q6_cutoff
    double max_tolerance_d = 0.0;

    /// The gather's reach for origins of radius ≤ r_origin and candidates of radius ≤
    /// r_other: a contact lies within r_o + r_j + δ_max·d, a bond within q6·(r_o + r_j).
    [[nodiscard]] double close_for(double r_origin, double r_other) const {
        return std::max(r_origin + r_other + max_tolerance_d, q6_factor * (r_origin + r_other)) *
               (1.0 + 1e-9);
    }

    Setup(const std::vector<Particle>& particles, const LocalStructureOptions& options)
        : tolerances(options.tolerances.size()),
          bins(options.bins),
          width(options.bin_width_over_d * options.mean_diameter),
          per_width(1.0 / width),
          outer(bin_outer(options.bins - 1, width)),
          split(options.mean_diameter, outer),
          split_first_bin(bin_of(split.lo[0], 1.0 / width) - 1),
          split_bins(bin_of(split.hi[1], 1.0 / width) + 1 - split_first_bin),
          q6_cutoff(options.q6_cutoff) {
        const double d = options.mean_diameter;
        double max_radius = 0.0;
        for (const Particle& p : particles) {
            max_radius = std::max(max_radius, p.radius);
        }
        radius = max_radius;
        equal = std::all_of(particles.begin(), particles.end(),
                            [&](const Particle& p) { return p.radius == max_radius; });
        const double max_tolerance = tolerances == 0 ? 0.0
                                                     : *std::max_element(options.tolerances.begin(),
                                                                         options.tolerances.end());
        for (const double t : options.tolerances) {
            thresholds.push_back(t * d);
        }
        max_threshold = max_tolerance * d;
        // The pair-counting pass bins distances below `outer` only; contacts and bonds are
        // gathered apart within `close` (for a wide blend 2·r_max far exceeds the g(r) range).
        reach = outer;
        reach_squared = reach * reach;
        // Widened far beyond rounding: the exact tests below decide.
        const double close =
            std::max(2.0 * max_radius + max_threshold, q6_cutoff * 2.0 * max_radius) * (1.0 + 1e-9);
        close_squared = close * close;
        q6_factor = options.q6_cutoff;
        max_tolerance_d = max_threshold;
        const SizeClasses sizes = size_classes(particles);  // size_classes.hpp
        split_sizes = sizes.wide();
        small_radius = sizes.small_max_radius;
        kernel.reach_squared = reach_squared;
        kernel.per_width = per_width;
        kernel.bins = static_cast<std::uint32_t>(bins);
        kernel.split_first = static_cast<std::uint32_t>(split_first_bin);
        kernel.split_bins = static_cast<std::uint32_t>(split_bins);
        for (int w = 0; w < 2; ++w) {
            kernel.split_lo[w] = split.lo[w];
            kernel.split_hi[w] = split.hi[w];
        }
    }
};

/// A neighbour close enough to be a contact or a bond.
struct Close {
    std::uint32_t origin;  // position in the origins' grid
    Index index;           // into the particles
    double distance;
    std::uint32_t position;  // in its grid
    std::uint32_t grid;      // in CloseGrids::grids
};

/// Buffers of one work item, reused for each of its origins.
struct Scratch {
    std::vector<Close> close;
    std::vector<Close> sorted;          // gather_close's counting sort
    std::vector<std::uint32_t> starts;  //
    std::vector<int> z;
    std::vector<std::int64_t> lanes;  // kBinLanes × (bins + 1), lane-major (count_bins)
    std::int64_t split[2] = {0, 0};   // pairs in the split windows
};

/// The g(r) and split-window counts of the origins of one column of the origins' grid:
/// pairs with the origins after each of them (weight 2: both are origins) and with every
/// other particle (weight 1), over the sliding windows of PairColumns::for_each_column.
void count_column_pairs(const PairColumns& origin_grid, const PairColumns& other_grid,
                        std::size_t column, const Setup& s, Scratch& scratch) {
    const std::size_t begin = origin_grid.column_begin(column);
    const std::size_t end = origin_grid.column_begin(column + 1);
    if (begin == end) {
        return;
    }
    const std::array<double, 4> footprint = origin_grid.footprint(begin, end);
    for (const PairColumns* grid : {&origin_grid, &other_grid}) {
        const bool origins = grid == &origin_grid;
        grid->for_each_column(
            footprint, s.reach, origins ? column : 0,
            [&](std::size_t c, std::size_t first, std::size_t last, double half) {
                count_column_bins(origin_grid.x.data(), origin_grid.y.data(), origin_grid.z.data(),
                                  begin, end, grid->x.data(), grid->y.data(), grid->z.data(), first,
                                  last, half, origins && c == column, origins ? 2 : 1, s.kernel,
                                  scratch.lanes.data(), scratch.split);
            });
    }
}

/// The grids contacts and bonds are gathered from: the origins' and the other particles'
/// grids, or for a wide blend the same split into small spheres (r ≤ r_max / 2) and large
/// ones, each searched within its own reach. Close::grid indexes this list.
struct CloseGrids {
    std::vector<const PairColumns*> grids;
    std::vector<double> max_radius;  // of each grid's particles (r_max when not split)
};

/// Fills scratch.close with the centres close enough to an origin of the column
/// [begin, end) of the origins' grid to be a contact or a bond (every grid of `close`, the
/// origin itself left out), sorted by origin, then particle index.
void gather_close(const PairColumns& origin_grid, const CloseGrids& close,
                  const std::vector<Particle>& particles, std::size_t begin, std::size_t end,
                  const Setup& s, Scratch& scratch) {
    scratch.close.clear();
    if (begin == end) {
        return;
    }
    const std::array<double, 4> footprint = origin_grid.footprint(begin, end);
    double column_radius = s.radius;  // the largest origin of the column
    if (s.split_sizes) {
        column_radius = 0.0;
        for (std::size_t o = begin; o < end; ++o) {
            column_radius = std::max(column_radius, particles[origin_grid.index[o]].radius);
        }
    }
    for (std::size_t g = 0; g < close.grids.size(); ++g) {
        const PairColumns* grid = close.grids[g];
        const double reach = s.split_sizes ? s.close_for(column_radius, close.max_radius[g])
                                           : std::sqrt(s.close_squared);
        const double reach_squared = s.split_sizes ? reach * reach : s.close_squared;
        grid->for_each_column(
            footprint, reach, 0,
            [&](std::size_t, std::size_t first, std::size_t last, double half) {
                for_each_pair_within(
                    origin_grid.x.data(), origin_grid.y.data(), origin_grid.z.data(), begin, end,
                    grid->x.data(), grid->y.data(), grid->z.data(), first, last, half, false,
                    reach_squared, [&](std::size_t p, std::size_t k, double q) {
                        if (grid->index[k] != origin_grid.index[p]) {
                            scratch.close.push_back({static_cast<std::uint32_t>(p), grid->index[k],
                                                     std::sqrt(q), static_cast<std::uint32_t>(k),
                                                     static_cast<std::uint32_t>(g)});
                        }
                    });
            });
    }
    // By origin (a counting sort over the column's positions), then index within each
    // origin's few: the one order of distinct (origin, index) keys.
    std::vector<std::uint32_t>& start = scratch.starts;
    start.assign(end - begin + 1, 0);
    for (const Close& c : scratch.close) {
        ++start[c.origin - begin + 1];
    }
    for (std::size_t o = 0; o + 1 < start.size(); ++o) {
        start[o + 1] += start[o];
    }
    scratch.sorted.resize(scratch.close.size());
    for (const Close& c : scratch.close) {
        scratch.sorted[start[c.origin - begin]++] = c;
    }
    std::swap(scratch.close, scratch.sorted);
    std::size_t from = 0;
    for (std::size_t o = 0; o + 1 < start.size(); ++o) {  // start[o]: the end of origin o
        std::sort(scratch.close.begin() + static_cast<std::ptrdiff_t>(from),
                  scratch.close.begin() + static_cast<std::ptrdiff_t>(start[o]),
                  [](const Close& u, const Close& v) { return u.index < v.index; });
        from = start[o];
    }
}

/// Z at every tolerance and the Q6 bond sums of one origin, bonds summed in increasing
/// particle index (which fixes their rounding whatever the grid or the thread count).
BondSums contacts_and_bonds(const std::vector<Particle>& particles, const Particle& a,
                            const Setup& s, const CloseGrids& grids, const Close* first,
                            const Close* last, Scratch& scratch) {
    std::fill(scratch.z.begin(), scratch.z.end(), 0);
    BondSums bonds;
    for (const Close* close = first; close != last; ++close) {
        const Close& c = *close;
        // The grid's copy of the centre (in cache) and, for equal spheres, the one radius.
        const PairColumns& grid = *grids.grids[c.grid];
        const double rb = s.equal ? s.radius : particles[c.index].radius;
        const double gap = c.distance - a.radius - rb;
        if (gap <= s.max_threshold) {
            for (std::size_t t = 0; t < s.tolerances; ++t) {
                scratch.z[t] += gap <= s.thresholds[t] ? 1 : 0;
            }
        }
        if (c.distance <= s.q6_cutoff * (a.radius + rb) && c.distance > 0.0) {
            const Vec3 bond(grid.x[c.position] - a.center.x(), grid.y[c.position] - a.center.y(),
                            grid.z[c.position] - a.center.z());
            bonds.add(bond / c.distance);
        }
    }
    return bonds;
}

/// Adds one origin's Z, wall contacts, shell volumes and bonds to the work item's sums.
void add_origin(const Particle& a, const BondSums& bonds, const Setup& s,
                const LocalStructureOptions& options, const std::vector<int>& z, Partial& part) {
    const auto walls = wall_gaps(a, options.container);
    for (std::size_t t = 0; t < s.tolerances; ++t) {
        part.z_sum[t] += z[t];
        ++part.z_histogram[t][std::min<std::size_t>(z[t], kMaxZ)];
        for (const double gap : walls) {
            part.wall_contacts[t] += gap <= s.thresholds[t] ? 1 : 0;
        }
    }
    if (shells_inside(a.center, s.outer, options.space)) {
        ++part.full_shell_origins;
    } else {
        ++part.corrected_origins;
        add_shell_volumes(a.center, s.width, options.bins, options.space, part.shell_volume);
        if (s.split.inside_range) {
            s.split.add_volumes(a.center, options.space, part.split_volume);
        }
    }
    if (bonds.bonds > 0) {
        part.global.add(bonds);
        part.q6_local_sum += bonds.q6();
        ++part.origins_with_bonds;
    }
}

Coordination finish_coordination(const Partial& total, const LocalStructureOptions& options,
                                 std::int64_t n) {
    Coordination c;
    c.tolerances = options.tolerances;
    c.origins = n;
    c.wall_contacts = total.wall_contacts;
    for (std::size_t t = 0; t < options.tolerances.size(); ++t) {
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
    return c;
}

Rdf finish_rdf(const Partial& total, const Setup& s, const LocalStructureOptions& options,
               std::size_t particles, std::int64_t n) {
    Rdf rdf;
    rdf.bin_width_over_d = options.bin_width_over_d;
    rdf.pairs = total.pairs;
    rdf.shell_volume = total.shell_volume;
    const auto full = static_cast<double>(total.full_shell_origins);
    for (std::size_t k = 0; k < options.bins; ++k) {
        const double r0 = bin_inner(k, s.width);
        const double r1 = bin_outer(k, s.width);
        rdf.shell_volume[k] +=
            full * (4.0 * std::numbers::pi / 3.0) * (r1 * r1 * r1 - r0 * r0 * r0);
    }
    rdf.origins = n;
    rdf.corrected_origins = total.corrected_origins;
    rdf.space = options.space;
    rdf.density_rule = options.density_rule;
    rdf.space_density = static_cast<double>(particles) / options.space.volume();
    if (s.split.inside_range) {
        for (int w = 0; w < 2; ++w) {
            rdf.split_pairs[w] = total.split_pairs[w];
            rdf.split_volume[w] = total.split_volume[w] + full * s.split.full_volume(w);
        }
    }
    normalise(rdf);
    return rdf;
}

BondOrder finish_bond_order(const Partial& total, const LocalStructureOptions& options) {
    BondOrder q;
    q.cutoff = options.q6_cutoff;
    q.q6_global = total.global.q6();
    q.origins_with_bonds = total.origins_with_bonds;
    q.q6_local_mean = total.origins_with_bonds > 0
                          ? total.q6_local_sum / static_cast<double>(total.origins_with_bonds)
                          : 0.0;
    return q;
}

/// The indices of [0, n) not in `subset` (sorted), increasing.
std::vector<Index> others(std::size_t n, const std::vector<Index>& subset) {
    std::vector<char> in(n, 0);
    for (const Index i : subset) {
        in[i] = 1;
    }
    std::vector<Index> rest;
    for (std::size_t i = 0; i < n; ++i) {
        if (in[i] == 0) {
            rest.push_back(static_cast<Index>(i));
        }
    }
    return rest;
}

}  // namespace

LocalStructure measure_local_structure(const std::vector<Particle>& particles,
                                       const std::vector<Index>& origins,
                                       const LocalStructureOptions& options) {
    const Setup s(particles, options);
    // g(r) counts each pair once: origin–origin pairs from their earlier member in the
    // origins' grid (weight 2, both are origins), origin–other pairs from the origin.
    // Origins are visited in the grid's stored order (column by column: near in space).
    const double side = kPairPassColumnSide * options.mean_diameter;
    const PairColumns origin_grid(particles, origins, side, options.threads);
    const std::vector<Index> rest = others(particles.size(), origins);
    const PairColumns other_grid(particles, rest, side, options.threads);
    // A wide blend's contacts and bonds: small and large spheres apart (Setup::split_sizes).
    std::vector<std::unique_ptr<PairColumns>> size_grids;
    CloseGrids grids{{&origin_grid, &other_grid}, {s.radius, s.radius}};
    if (s.split_sizes) {
        grids = {};
        for (const std::vector<Index>* members : {&origins, &rest}) {
            std::vector<Index> small;
            std::vector<Index> large;
            double large_radius = 0.0;
            for (const Index i : *members) {
                const bool is_large = particles[i].radius > s.small_radius;  // large()
                (is_large ? large : small).push_back(i);
                large_radius =
                    is_large ? std::max(large_radius, particles[i].radius) : large_radius;
            }
            size_grids.push_back(
                std::make_unique<PairColumns>(particles, small, side, options.threads));
            grids.grids.push_back(size_grids.back().get());
            grids.max_radius.push_back(s.small_radius);
            size_grids.push_back(
                std::make_unique<PairColumns>(particles, large, side, options.threads));
            grids.grids.push_back(size_grids.back().get());
            grids.max_radius.push_back(large_radius);
        }
    }
    const Partial total = chunked_reduce(
        options.threads, origin_grid.columns(), kColumnsPerChunk,
        Partial(s.tolerances, options.bins),
        [&](Partial& part, std::size_t first, std::size_t last) {
            Scratch scratch;
            scratch.z.resize(s.tolerances);
            scratch.lanes.assign(kBinLanes * (s.bins + 1), 0);
            for (std::size_t column = first; column < last; ++column) {
                count_column_pairs(origin_grid, other_grid, column, s, scratch);
            }
            for (std::size_t column = first; column < last; ++column) {
                const std::size_t begin = origin_grid.column_begin(column);
                const std::size_t end = origin_grid.column_begin(column + 1);
                gather_close(origin_grid, grids, particles, begin, end, s, scratch);
                const Close* close = scratch.close.data();
                const Close* const close_end = close + scratch.close.size();
                for (std::size_t o = begin; o < end; ++o) {
                    const Close* next = close;
                    while (next != close_end && next->origin == o) {
                        ++next;
                    }
                    Particle a;  // the centre and radius of the origin (id unused)
                    a.center = Vec3(origin_grid.x[o], origin_grid.y[o], origin_grid.z[o]);
                    a.radius = s.equal ? s.radius : particles[origin_grid.index[o]].radius;
                    const BondSums bonds =
                        contacts_and_bonds(particles, a, s, grids, close, next, scratch);
                    add_origin(a, bonds, s, options, scratch.z, part);
                    close = next;
                }
            }
            for (std::size_t l = 0; l < kBinLanes; ++l) {
                for (std::size_t k = 0; k < s.bins; ++k) {  // not the dump bin k = bins
                    part.pairs[k] += scratch.lanes[l * (s.bins + 1) + k];
                }
            }
            part.split_pairs[0] += scratch.split[0];
            part.split_pairs[1] += scratch.split[1];
        },
        [](Partial& sum, const Partial& part) { sum.add(part); });

    LocalStructure result;
    const auto n = static_cast<std::int64_t>(origins.size());
    result.coordination = finish_coordination(total, options, n);
    result.rdf = finish_rdf(total, s, options, particles.size(), n);
    result.bond_order = finish_bond_order(total, options);
    return result;
}

}  // namespace sgmp::metrics
