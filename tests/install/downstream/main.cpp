// Makes a 150-sphere pack through the installed engine and writes it: the same bytes as
// `sgmp pack --count 150 --arrangement loose-random --seed 3`. Prints its φ measured by the
// installed metrics library (shortest round-trip digits, as `sgmp-compare measure` writes
// it) and a mean by the installed report library.
#include <charconv>
#include <string>
#include <iostream>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/metrics/measure.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/report/statistics.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: downstream OUT.xyz\n";
        return 2;
    }
    sgmp::engine::PackRequest request;
    request.count = 150;
    request.arrangement = sgmp::engine::Arrangement::LooseRandom;
    request.seed = 3;
    const sgmp::Pack pack = sgmp::engine::make_pack(request);
    sgmp::write_pack_file(argv[1], pack, false);
    const auto shortest = [](double value) {
        char digits[32];
        return std::string(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
    };
    // The file as written, read back: what `sgmp-compare measure` sees.
    const auto measured =
        sgmp::metrics::measure(sgmp::read_pack_file(argv[1]), sgmp::metrics::MeasureOptions{});
    std::cout << "\"phi\": " << shortest(measured.phi) << '\n';
    std::cout << "mean " << shortest(sgmp::report::mean({1.0, 2.0, 4.0})) << '\n';
    return 0;
}
