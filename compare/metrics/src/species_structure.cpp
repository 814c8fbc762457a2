#include "sgmp/metrics/species_structure.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <utility>

#include "sgmp/metrics/local_structure.hpp"
#include "sgmp/metrics/pair_columns.hpp"
#include "sgmp/metrics/pair_kernels.hpp"
#include "sgmp/metrics/parallel.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"

namespace sgmp::metrics {
namespace {

// Fixed work items (never from the thread count), and with them every sum's order.
constexpr std::size_t kColumnsPerChunk = 64;
constexpr std::size_t kOriginsPerChunk = 4096;

/// The centres of one species: all of them, those in the region, and their radii.
struct Members {
    int species = 0;
    std::vector<Index> all;
    std::vector<Index> origins;
    std::int64_t count = 0;  // the pack's own (images left out)
    double radius_sum = 0.0;
    bool one_radius = true;
    double radius = 0.0;  // the one radius when one_radius
};

std::vector<Members> members_of(const std::vector<Particle>& particles, const Box& region,
                                std::size_t originals) {
    std::map<int, Members> by_species;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Particle& p = particles[i];
        Members& m = by_species[p.species];
        if (m.all.empty()) {
            m.species = p.species;
            m.radius = p.radius;
        }
        m.one_radius = m.one_radius && p.radius == m.radius;
        m.all.push_back(static_cast<Index>(i));
        if (i >= originals) {
            continue;
        }
        m.radius_sum += p.radius;
        ++m.count;
        if (region.contains(p.center)) {
            m.origins.push_back(static_cast<Index>(i));
        }
    }
    std::vector<Members> result;
    for (auto& [species, m] : by_species) {
        result.push_back(std::move(m));
    }
    return result;
}

/// Bin edges of a pair type: bin k centred on k·ΔR + o (bin 0 from 0).
struct Bins {
    double width;
    double offset;
    std::size_t count;

    [[nodiscard]] double inner(std::size_t k) const {
        return k == 0 ? 0.0 : (static_cast<double>(k) - 0.5) * width + offset;
    }
    [[nodiscard]] double outer(std::size_t k) const {
        return (static_cast<double>(k) + 0.5) * width + offset;
    }
    /// The bin of distance s (count for beyond the last).
    [[nodiscard]] std::size_t of(double s) const {
        const double t = (s - offset) / width + 0.5;
        if (t < 1.0) {
            return 0;
        }
        return t >= static_cast<double>(count) ? count : static_cast<std::size_t>(t);
    }
};

/// Pair counts per bin and contact counts per tolerance of (origins of I, centres of J).
struct PairCounts {
    std::vector<std::int64_t> pairs;
    std::vector<std::int64_t> contacts;

    PairCounts(std::size_t bins, std::size_t tolerances)
        : pairs(bins + 1, 0), contacts(tolerances, 0) {}
    void add(const PairCounts& o) {
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            pairs[k] += o.pairs[k];
        }
        for (std::size_t t = 0; t < contacts.size(); ++t) {
            contacts[t] += o.contacts[t];
        }
    }
};

PairCounts count_pairs(const std::vector<Particle>& particles, const PairColumns& origins,
                       const PairColumns& targets, bool same_species, const Bins& bins,
                       const std::vector<double>& thresholds, double close, unsigned threads) {
    const double reach = bins.outer(bins.count - 1);
    const double limit = std::max(reach, close);
    return chunked_reduce(
        threads, origins.columns(), kColumnsPerChunk, PairCounts(bins.count, thresholds.size()),
        [&](PairCounts& part, std::size_t first, std::size_t last) {
            for (std::size_t column = first; column < last; ++column) {
                const std::size_t begin = origins.column_begin(column);
                const std::size_t end = origins.column_begin(column + 1);
                targets.for_each_column(
                    origins.footprint(begin, end), limit, 0,
                    [&](std::size_t, std::size_t from, std::size_t to, double half) {
                        for_each_pair_within(
                            origins.x.data(), origins.y.data(), origins.z.data(), begin, end,
                            targets.x.data(), targets.y.data(), targets.z.data(), from, to, half,
                            false, limit * limit * (1.0 + 1e-12),
                            [&](std::size_t p, std::size_t k, double q) {
                                const Index a = origins.index[p];
                                const Index b = targets.index[k];
                                if (same_species && a == b) {
                                    return;
                                }
                                const double s = std::sqrt(q);
                                ++part.pairs[bins.of(s)];
                                const double gap = s - particles[a].radius - particles[b].radius;
                                for (std::size_t t = 0; t < thresholds.size(); ++t) {
                                    part.contacts[t] += gap <= thresholds[t] ? 1 : 0;
                                }
                            });
                    });
            }
        },
        [](PairCounts& total, const PairCounts& part) { total.add(part); });
}

/// Σ over `origins` of the volume inside `space` of each bin's shell.
std::vector<double> shell_volumes(const std::vector<Particle>& particles,
                                  const std::vector<Index>& origins, const Bins& bins,
                                  const Box& space, unsigned threads) {
    const double last_outer = bins.outer(bins.count - 1);
    return chunked_reduce(
        threads, origins.size(), kOriginsPerChunk, std::vector<double>(bins.count, 0.0),
        [&](std::vector<double>& part, std::size_t first, std::size_t last) {
            for (std::size_t o = first; o < last; ++o) {
                const Vec3& c = particles[origins[o]].center;
                const bool full = shells_inside(c, last_outer, space);
                double inner = 0.0;
                for (std::size_t k = 0; k < bins.count; ++k) {
                    const double r = bins.outer(k);
                    const double outer =
                        full ? 4.0 * std::numbers::pi / 3.0 * r * r * r
                             : sphere_box_volume(c, r, space, SphereBoxQuadrature::GaussLegendre);
                    part[k] += outer - inner;
                    inner = outer;
                }
            }
        },
        [](std::vector<double>& total, const std::vector<double>& part) {
            for (std::size_t k = 0; k < total.size(); ++k) {
                total[k] += part[k];
            }
        });
}

}  // namespace

std::optional<SpeciesStructure> measure_species_structure(const std::vector<Particle>& particles,
                                                          const SpeciesStructureOptions& options) {
    if (!has_species(particles)) {
        return std::nullopt;
    }
    const std::vector<Members> members = members_of(particles, options.region, options.originals);
    if (members.size() < 2) {
        return std::nullopt;
    }
    const double d = options.mean_diameter;
    const double width = options.bin_width_over_d * d;
    std::vector<double> thresholds;
    double max_tolerance = 0.0;
    for (const double t : options.tolerances) {
        thresholds.push_back(t * d);
        max_tolerance = std::max(max_tolerance, t);
    }
    // A pair type's contacts lie within r_I,max + r_J,max + δ·d: its own window, so that
    // the small spheres of a wide blend are not searched out to twice the largest radius.
    std::vector<double> largest(members.size(), 0.0);
    for (std::size_t a = 0; a < members.size(); ++a) {
        for (const Index i : members[a].all) {
            largest[a] = std::max(largest[a], particles[i].radius);
        }
    }
    const auto close_of = [&](std::size_t a, std::size_t b) {
        return (largest[a] + largest[b] + max_tolerance * d) * (1.0 + 1e-9);
    };
    const double side = kPairPassColumnSide * d;
    std::vector<std::unique_ptr<PairColumns>> origin_columns;
    std::vector<std::unique_ptr<PairColumns>> all_columns;
    for (const Members& m : members) {
        origin_columns.push_back(
            std::make_unique<PairColumns>(particles, m.origins, side, options.threads));
        all_columns.push_back(
            std::make_unique<PairColumns>(particles, m.all, side, options.threads));
    }
    const double space_volume = options.space.volume();

    SpeciesStructure result;
    const std::size_t n = members.size();
    std::vector<std::vector<std::vector<double>>> z(n, std::vector<std::vector<double>>(n));
    std::vector<std::pair<std::size_t, std::size_t>> pair_of;  // (I, J) of result.pairs
    for (std::size_t a = 0; a < n; ++a) {
        for (std::size_t b = 0; b < n; ++b) {
            const Members& I = members[a];
            const Members& J = members[b];
            const double contact = I.radius + J.radius;
            const double offset =
                I.one_radius && J.one_radius ? contact - width * std::round(contact / width) : 0.0;
            const Bins bins{width, offset, options.bins};
            const PairCounts counts =
                count_pairs(particles, *origin_columns[a], *all_columns[b], a == b, bins,
                            thresholds, close_of(a, b), options.threads);
            const auto origins = static_cast<double>(I.origins.size());
            for (const std::int64_t c : counts.contacts) {
                z[a][b].push_back(origins > 0.0 ? static_cast<double>(c) / origins : 0.0);
            }
            if (b < a) {
                continue;
            }
            SpeciesPair pair;
            pair.i = I.species;
            pair.j = J.species;
            pair.bin_offset_over_d = offset / d;
            pair.pairs.assign(counts.pairs.begin(), counts.pairs.end() - 1);  // not beyond
            pair.shell_volume =
                shell_volumes(particles, I.origins, bins, options.space, options.threads);
            // g and ρ_J as g(r) normalises them (rdf.hpp: one density rule, one g).
            Rdf rdf;
            rdf.bin_width_over_d = options.bin_width_over_d;
            rdf.density_rule = options.density_rule;
            rdf.pairs = pair.pairs;
            rdf.shell_volume = pair.shell_volume;
            rdf.space_density = static_cast<double>(J.all.size()) / space_volume;
            normalise(rdf);
            pair.density = rdf.density;
            pair.g = std::move(rdf.g);
            result.pairs.push_back(std::move(pair));
            pair_of.emplace_back(a, b);
        }
    }
    for (std::size_t p = 0; p < result.pairs.size(); ++p) {
        const auto [a, b] = pair_of[p];
        result.pairs[p].z_ij = z[a][b];
        result.pairs[p].z_ji = z[b][a];
    }
    for (std::size_t a = 0; a < n; ++a) {
        SpeciesSummary s;
        s.species = members[a].species;
        s.origins = static_cast<std::int64_t>(members[a].origins.size());
        s.count = members[a].count;
        s.diameter_over_d = 2.0 * members[a].radius_sum / static_cast<double>(members[a].count) / d;
        s.z_mean.assign(thresholds.size(), 0.0);
        for (std::size_t b = 0; b < n; ++b) {
            for (std::size_t t = 0; t < thresholds.size(); ++t) {
                s.z_mean[t] += z[a][b][t];
            }
        }
        result.species.push_back(std::move(s));
    }
    return result;
}

}  // namespace sgmp::metrics
