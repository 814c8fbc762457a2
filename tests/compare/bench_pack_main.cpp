// Writes a deterministic jittered-FCC pack for the benchmark (scripts/bench-compare):
//   sgmp-compare-bench-pack COUNT OUT [SEED]
#include <cstdlib>
#include <iostream>
#include <string>

#include "sgmp/pack/pack_file.hpp"
#include "synthetic_packs.hpp"

int main(int argc, char** argv) {
    if (argc < 3 || argc > 4) {
        std::cerr << "usage: sgmp-compare-bench-pack COUNT OUT [SEED]\n";
        return 2;
    }
    try {
        const auto count = std::stoull(argv[1]);
        const auto seed = argc == 4 ? std::stoull(argv[3]) : 1ULL;
        // Nearest neighbours 1.06 d apart with ±0.015 d jitter: φ ≈ 0.62, no overlaps.
        const auto pack = sgmp::testing::jittered_fcc_pack(count, 1.06, 0.015, seed);
        sgmp::write_pack_file(argv[2], pack, true);
    } catch (const std::exception& error) {
        std::cerr << "sgmp-compare-bench-pack: " << error.what() << '\n';
        return 1;
    }
    return 0;
}
