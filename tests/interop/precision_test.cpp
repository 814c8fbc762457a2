// Overlaps from text precision: the grid search against all pairs, and the ASE case (a pack
// without overlaps written with 8 decimals reads back with overlaps, all within the bound).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/pack/random.hpp"
#include "sgmp/pack/text_precision.hpp"
#include "sgmp/pack/xyz_format.hpp"

using namespace sgmp;

BOOST_AUTO_TEST_SUITE(text_precision)

BOOST_AUTO_TEST_CASE(grid_search_finds_the_pairs_of_the_all_pairs_loop) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        Random random(seed);
        std::vector<Particle> particles;
        for (int i = 0; i < 300; ++i) {
            particles.push_back(Particle{
                i + 1, Vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)),
                random.uniform(0.01, 0.08), 0});
        }
        const int decimals = static_cast<int>(seed % 4);  // bounds 2.7 down to 0.0027
        std::size_t overlaps = 0;
        std::size_t within = 0;
        for (std::size_t i = 0; i < particles.size(); ++i) {
            for (std::size_t j = i + 1; j < particles.size(); ++j) {
                if (sgmp::overlaps(particles[i], particles[j]) &&
                    -surface_gap(particles[i], particles[j]) > 1e-4) {
                    ++overlaps;
                    within += -surface_gap(particles[i], particles[j]) <=
                                      (std::sqrt(3.0) + 1.0) * std::pow(10.0, -decimals)
                                  ? 1
                                  : 0;
                }
            }
        }
        const PrecisionOverlaps found = precision_overlaps(particles, decimals, 1e-4);
        BOOST_TEST(found.overlaps == overlaps);
        BOOST_TEST(found.within_precision == within);
        BOOST_TEST(overlaps > 0u);
    }
}

BOOST_AUTO_TEST_CASE(eight_decimals_make_overlaps_that_the_bound_explains) {
    engine::PackRequest request;
    request.count = 600;
    request.arrangement = engine::Arrangement::LooseRandom;
    request.seed = 4;
    const Pack pack = engine::make_pack(request);
    std::ostringstream full;
    write_xyz(full, pack);
    std::istringstream full_in(full.str());
    const PackRead exact = read_xyz(full_in, "full", {});
    const double floor = 1e-9 * *pack.metadata.get_number("diameter");
    BOOST_TEST(precision_overlaps(exact.pack.particles, *exact.decimals, floor).overlaps == 0u);
    // As ASE writes it: fixed 8 decimals.
    std::string text = std::to_string(pack.particles.size()) + "\nProperties=pos:R:3:radius:R:1\n";
    char line[200];
    for (const auto& p : pack.particles) {
        std::snprintf(line, sizeof line, "%.8f %.8f %.8f %.8f\n", p.center.x(), p.center.y(),
                      p.center.z(), p.radius);
        text += line;
    }
    std::istringstream in(text);
    const PackRead lossy = read_xyz(in, "ase", {});
    BOOST_TEST(*lossy.decimals == 8);
    const PrecisionOverlaps found = precision_overlaps(lossy.pack.particles, 8, floor);
    BOOST_TEST(found.overlaps > 0u);
    BOOST_TEST(found.within_precision == found.overlaps);
    BOOST_TEST(found.max_overlap <= found.bound);
    BOOST_TEST(found.bound == (std::sqrt(3.0) + 1.0) * 1e-8);
}

BOOST_AUTO_TEST_SUITE_END()
