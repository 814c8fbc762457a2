// Times the Voronoi local packing fraction on a pack file (scripts/bench-compare):
//   sgmp-compare-bench-voronoi PACK [THREADS]   (THREADS: 0, the default, means all cores)
// prints the wall-clock and CPU seconds to read the pack and to tessellate it, for the
// control volume and for every centre, with the results.
#include <chrono>
#include <ctime>
#include <iostream>
#include <limits>

#include "sgmp/metrics/measure.hpp"
#include "sgmp/metrics/parallel.hpp"
#include "sgmp/metrics/voronoi.hpp"
#include "sgmp/pack/pack_file.hpp"

namespace {

struct Stopwatch {
    std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
    std::clock_t cpu = std::clock();
};

std::ostream& operator<<(std::ostream& out, const Stopwatch& start) {
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start.wall).count();
    const double cpu = static_cast<double>(std::clock() - start.cpu) / CLOCKS_PER_SEC;
    return out << wall << " s (CPU " << cpu << " s)";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::cerr << "usage: sgmp-compare-bench-voronoi PACK [THREADS]\n";
        return 2;
    }
    try {
        sgmp::metrics::VoronoiOptions options;
        options.threads = argc == 3 ? static_cast<unsigned>(std::stoul(argv[2])) : 0U;
        Stopwatch start;
        const sgmp::Pack pack = sgmp::read_pack_file(argv[1]);
        std::cout << "read " << start << ", " << pack.particles.size() << " particles\n";
        const sgmp::Container container = sgmp::metrics::container_of(pack);
        const sgmp::Box everything = container.box_up_to(std::numeric_limits<double>::infinity());
        for (const auto& [label, region] :
             {std::pair{"control-volume", sgmp::control_volume()}, std::pair{"all", everything}}) {
            start = Stopwatch{};
            const auto phi =
                sgmp::metrics::voronoi_local_phi(pack.particles, container, region, options);
            std::cout << "voronoi " << label << ' ' << start << ", " << phi.cells << " cells, mean "
                      << phi.mean << " sd " << phi.sd << " global " << phi.global << '\n';
        }
    } catch (const std::exception& error) {
        std::cerr << "sgmp-compare-bench-voronoi: " << error.what() << '\n';
        return 1;
    }
    return 0;
}
