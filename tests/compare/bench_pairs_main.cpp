// The pair rate of the metrics' fused pass against a minimal loop over the same pairs
// (scripts/bench-analysis):
//   sgmp-compare-bench-pairs PACK
// Origins are the centres in the control volume, neighbours every particle within the
// g(r) range 5·d (+ half a bin), as in `sgmp-compare measure`. Times, in CPU seconds of one
// thread (so the figures hold on a loaded machine):
//   scan     the candidates of the pass's column windows (every origin's windows in both
//            grids, whole): squared distances and a count of those within reach, one at
//            a time (the pass, eight candidates per instruction where the CPU has
//            AVX-512, skipping empty windows and visiting origin pairs once, runs faster);
//   bins     the same plus the square root and the g(r) histogram;
//   pass     measure_local_structure itself (g(r), split ratio, Z at six tolerances, Q6).
// Prints "pairs N", then one "<name> <seconds> s <pairs per second>" line per loop.
#include <algorithm>
#include <cmath>
#include <ctime>
#include <iostream>

#include "sgmp/metrics/local_structure.hpp"
#include "sgmp/metrics/measure.hpp"
#include "sgmp/metrics/pair_columns.hpp"
#include "sgmp/metrics/parallel.hpp"
#include "sgmp/metrics/spatial_order.hpp"
#include "sgmp/pack/pack_file.hpp"

namespace {

double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
    using namespace sgmp;
    using namespace sgmp::metrics;
    if (argc != 2) {
        std::cerr << "usage: sgmp-compare-bench-pairs PACK\n";
        return 2;
    }
    try {
        const Pack pack = read_pack_file(argv[1]);
        const double d = mean_diameter(pack);
        std::vector<Index> all(pack.particles.size());
        for (Index i = 0; i < all.size(); ++i) {
            all[i] = i;
        }
        std::vector<Particle> particles;
        for (const Index i : spatial_order(pack.particles, all, d, 1)) {
            particles.push_back(pack.particles[i]);
        }
        std::vector<Index> origins;
        for (Index i = 0; i < particles.size(); ++i) {
            if (control_volume().contains(particles[i].center)) {
                origins.push_back(i);
            }
        }
        const std::size_t bins = bins_for(5.0 / 0.02);
        const double width = 0.02 * d;
        const double reach = bin_outer(bins - 1, width);
        const double reach2 = reach * reach;
        // The pass's two sets of columns; every origin scans all its windows (the
        // centres of a column met with |z − z_p| ≤ half).
        std::vector<char> is_origin(particles.size(), 0);
        for (const Index i : origins) {
            is_origin[i] = 1;
        }
        std::vector<Index> rest;
        for (Index i = 0; i < particles.size(); ++i) {
            if (is_origin[i] == 0) {
                rest.push_back(i);
            }
        }
        const double side = kPairPassColumnSide * d;
        const PairColumns origin_grid(particles, origins, side, 1);
        const PairColumns other_grid(particles, rest, side, 1);
        const auto for_each_window = [&](auto&& f) {
            for (std::size_t c = 0; c < origin_grid.columns(); ++c) {
                const std::size_t begin = origin_grid.column_begin(c);
                const std::size_t end = origin_grid.column_begin(c + 1);
                for (const PairColumns* grid : {&origin_grid, &other_grid}) {
                    grid->for_each_column(
                        origin_grid.footprint(begin, end), reach, 0,
                        [&](std::size_t, std::size_t first, std::size_t last, double half) {
                            const auto z0 = grid->z.begin();
                            for (std::size_t p = begin; p < end; ++p) {
                                const double zp = origin_grid.z[p];
                                const auto from = std::lower_bound(
                                    z0 + static_cast<std::ptrdiff_t>(first),
                                    z0 + static_cast<std::ptrdiff_t>(last), zp - half);
                                const auto to = std::upper_bound(
                                    from, z0 + static_cast<std::ptrdiff_t>(last), zp + half);
                                f(*grid, p, static_cast<std::size_t>(from - z0),
                                  static_cast<std::size_t>(to - z0));
                            }
                        });
                }
            }
        };

        double start = cpu_seconds();
        std::size_t pairs = 0;
        for_each_window(
            [&](const PairColumns& grid, std::size_t p, std::size_t from, std::size_t to) {
                const double ax = origin_grid.x[p];
                const double ay = origin_grid.y[p];
                const double az = origin_grid.z[p];
                std::size_t n = 0;
                for (std::size_t k = from; k < to; ++k) {
                    const double dx = grid.x[k] - ax;
                    const double dy = grid.y[k] - ay;
                    const double dz = grid.z[k] - az;
                    n += (dx * dx + dy * dy + dz * dz <= reach2) ? 1 : 0;
                }
                pairs += n;
            });
        pairs -= origins.size();  // each origin itself
        const double scan = cpu_seconds() - start;

        start = cpu_seconds();
        std::vector<std::int64_t> histogram(bins + 1, 0);
        for_each_window(
            [&](const PairColumns& grid, std::size_t p, std::size_t from, std::size_t to) {
                for (std::size_t k = from; k < to; ++k) {
                    const double dx = grid.x[k] - origin_grid.x[p];
                    const double dy = grid.y[k] - origin_grid.y[p];
                    const double dz = grid.z[k] - origin_grid.z[p];
                    const double q = dx * dx + dy * dy + dz * dz;
                    const auto b = static_cast<std::size_t>(std::sqrt(q) / width + 0.5);
                    ++histogram[std::min(b, bins)];
                }
            });
        const double binned = cpu_seconds() - start;

        LocalStructureOptions options;
        options.tolerances = coordination_tolerances();
        options.mean_diameter = d;
        options.bins = bins;
        options.space = center_space(particles, container_of(pack), 0.5 * d);
        options.container = container_of(pack);
        options.threads = 1;
        start = cpu_seconds();
        const LocalStructure local = measure_local_structure(particles, origins, options);
        const double pass = cpu_seconds() - start;
        std::int64_t counted = 0;
        for (const std::int64_t n : local.rdf.pairs) {
            counted += n;
        }
        const auto rate = [&](double seconds) { return static_cast<double>(pairs) / seconds; };
        std::cout << "origins " << origins.size() << "\npairs " << pairs << " (g(r) counts "
                  << counted << ", histogram check " << histogram[0] - origins.size() << ")\n"
                  << "scan " << scan << " s " << rate(scan) << "\n"
                  << "bins " << binned << " s " << rate(binned) << "\n"
                  << "pass " << pass << " s " << rate(pass) << "\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "sgmp-compare-bench-pairs: " << e.what() << "\n";
        return 1;
    }
}
