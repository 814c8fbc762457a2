// The pair rate of the metrics' fused pass against a minimal loop over the same pairs
// (scripts/bench-analysis):
//   sgmp-compare-bench-pairs PACK
// Origins are the centres in the control volume, neighbours every particle within the
// g(r) range 5·d (+ half a bin), as in `sgmp-compare measure`. Times, in CPU seconds of one
// thread (so the figures hold on a loaded machine):
//   scan     the candidates of the column grid: squared distances and a count of those
//            within reach (the memory-bound floor of any pass over these pairs);
//   bins     the same plus the square root and the g(r) histogram;
//   pass     measure_local_structure itself (g(r), split ratio, Z at six tolerances, Q6).
// Prints "pairs N", then one "<name> <seconds> s <pairs per second>" line per loop.
#include <cmath>
#include <ctime>
#include <iostream>

#include "sgmp/compare/column_grid.hpp"
#include "sgmp/compare/local_structure.hpp"
#include "sgmp/compare/measure.hpp"
#include "sgmp/compare/parallel.hpp"
#include "sgmp/compare/spatial_order.hpp"
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
    using namespace sgmp::compare;
    if (argc != 2) {
        std::cerr << "usage: sgmp-compare-bench-pairs PACK\n";
        return 2;
    }
    try {
        set_thread_count(1);
        const Pack pack = read_pack_file(argv[1]);
        const double d = mean_diameter(pack);
        std::vector<Index> all(pack.particles.size());
        for (Index i = 0; i < all.size(); ++i) {
            all[i] = i;
        }
        std::vector<Particle> particles;
        for (const Index i : spatial_order(pack.particles, all, d)) {
            particles.push_back(pack.particles[i]);
        }
        std::vector<Index> origins;
        std::vector<Vec3> centres;
        for (Index i = 0; i < particles.size(); ++i) {
            centres.push_back(particles[i].center);
            if (control_volume().contains(particles[i].center)) {
                origins.push_back(i);
            }
        }
        const std::vector<Index> ordered = spatial_order(particles, origins, d);
        const std::size_t bins = bins_for(5.0 / 0.02);
        const double width = 0.02 * d;
        const double reach = bin_outer(bins - 1, width);
        const double reach2 = reach * reach;
        const ColumnGrid grid(particles, 0.5 * d);

        double start = cpu_seconds();
        std::size_t pairs = 0;
        for (const Index i : ordered) {
            const Vec3 c = particles[i].center;
            grid.for_each_range(c, reach, [&](std::size_t begin, std::size_t end) {
                std::size_t n = 0;
                for (std::size_t k = begin; k < end; ++k) {
                    const double dx = grid.x[k] - c.x();
                    const double dy = grid.y[k] - c.y();
                    const double dz = grid.z[k] - c.z();
                    n += (dx * dx + dy * dy + dz * dz <= reach2) ? 1 : 0;
                }
                pairs += n;
            });
            --pairs;  // itself
        }
        const double scan = cpu_seconds() - start;

        start = cpu_seconds();
        std::vector<std::int64_t> histogram(bins + 1, 0);
        for (const Index i : ordered) {
            const Vec3 c = particles[i].center;
            grid.for_each_range(c, reach, [&](std::size_t begin, std::size_t end) {
                for (std::size_t k = begin; k < end; ++k) {
                    const double dx = grid.x[k] - c.x();
                    const double dy = grid.y[k] - c.y();
                    const double dz = grid.z[k] - c.z();
                    const double q = dx * dx + dy * dy + dz * dz;
                    const auto b = static_cast<std::size_t>(std::sqrt(q) / width + 0.5);
                    ++histogram[std::min(b, bins)];
                }
            });
        }
        const double binned = cpu_seconds() - start;

        LocalStructureOptions options;
        options.tolerances = coordination_tolerances();
        options.mean_diameter = d;
        options.bins = bins;
        options.space = centre_space(particles, container_of(pack), 0.5 * d);
        options.container = container_of(pack);
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
