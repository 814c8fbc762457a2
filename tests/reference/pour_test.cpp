// Real pours with LIGGGHTS: 150 spheres, settled in about a second of computing each.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>

#include "run_program.hpp"
#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/pack_overlaps.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"
#include "sgmp/reference/pour.hpp"

namespace fs = std::filesystem;
using namespace sgmp;
using namespace sgmp::reference;

namespace {

/// What every settled pour must satisfy. Tolerances: overlaps and wall penetrations
/// below 1 % of d (the stiffness was chosen for about 0.5 %); the control volume's packing
/// fraction between 0.50 and 0.68 (random packs of 150 spheres 0.29 wide, walls included,
/// measured 0.57-0.64; loose random packing is about 0.55, random close packing 0.64).
void check_settled_pack(const Pack& pack, std::size_t count, double threshold) {
    BOOST_TEST_REQUIRE(pack.particles.size() == count);
    const double d = diameter_for_count(count);
    for (std::size_t i = 0; i < pack.particles.size(); ++i) {
        BOOST_TEST(pack.particles[i].id == static_cast<std::int64_t>(i + 1));
        BOOST_TEST(pack.particles[i].radius == d / 2.0);
    }
    const OverlapCount overlaps = count_overlaps(pack.particles, Container{}, 0.0);
    BOOST_TEST(overlaps.max_wall < 0.01 * d);
    BOOST_TEST(overlaps.max_pair < 0.01 * d);
    BOOST_TEST(*pack.metadata.get_number("settling_measure") < threshold);
    const double phi = packing_fraction(pack, control_volume());
    BOOST_TEST(phi > 0.50);
    BOOST_TEST(phi < 0.68);
    BOOST_TEST(*pack.metadata.get("generator") == "liggghts");
    BOOST_TEST(*pack.metadata.get("liggghts_version") == "3.8.0");
    BOOST_TEST(*pack.metadata.get("container") == Container{}.to_string());
    BOOST_TEST(*pack.metadata.get_number("diameter") == d);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(liggghts_pours)

BOOST_AUTO_TEST_CASE(a_frictional_pour_of_150_settles_inside_the_container) {
    PourRequest request;
    request.parameters.count = 150;
    request.parameters.seed = 1;
    request.parameters.friction = 0.5;
    int fall_reports = 0;
    int settle_reports = 0;
    double last_ratio = 0.0;
    const PourResult result = pour(request, [&](const PourProgress& progress) {
        fall_reports += progress.phase == PourPhase::falling ? 1 : 0;
        settle_reports += progress.phase == PourPhase::settling ? 1 : 0;
        if (progress.phase == PourPhase::settling) {
            last_ratio = progress.ke_ratio;
        }
    });
    check_settled_pack(result.pack, 150, request.parameters.settle_threshold);
    BOOST_TEST(fall_reports == 20);   // the fall phase runs in 20 chunks
    BOOST_TEST(settle_reports >= 2);  // settled means calm at two consecutive checks
    BOOST_TEST(last_ratio < request.parameters.settle_threshold);
    BOOST_TEST(result.max_overlap_over_d == *result.pack.metadata.get_number("max_overlap_over_d"));
}

BOOST_AUTO_TEST_CASE(a_two_rank_near_frictionless_pour_from_an_arrangement) {
    const fs::path dir = testing::fresh_directory("sgmp-ref-pour");
    const fs::path out = dir / "pack.xyz.gz";
    testing::ProgramOptions options;
    options.args = {"pour",         "--count", "150",        "--seed", "2",
                    "--friction",   "0.01",    "--ranks",    "2",      "--from-arrangement",
                    "loose-random", "--out",   out.string(), "--quiet"};
    const testing::ProgramRun run = testing::run_program(SGMP_REFERENCE_EXE, options);
    BOOST_TEST_REQUIRE(run.exit_code == 0, run.stderr_text);
    const Pack pack = read_pack_file(out);
    check_settled_pack(pack, 150, 1e-6);
    BOOST_TEST(*pack.metadata.get("processor_grid") == "2 1 1");
    BOOST_TEST(*pack.metadata.get("arrangement") == "loose-random");
    BOOST_TEST(*pack.metadata.get_number("friction") == 0.01);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(liggghts_blend_pours)

// A bimodal blend (diameter ratio 1 : 0.5, equal volumes) in a periodic cell: the species
// hold the deterministic counts 67 : 533 of sgmp pack, every radius is its species' d/2
// exactly, the header says periodic, and the minimum-image overlaps stay soft (< 1 % of d).
BOOST_AUTO_TEST_CASE(a_periodic_bimodal_pour_of_600) {
    const fs::path dir = testing::fresh_directory("sgmp-ref-blend");
    const fs::path out = dir / "blend.xyz";
    testing::ProgramOptions options;
    options.args = {"pour",       "--count",      "600",           "--seed",
                    "3",          "--size-modes", "1:0.5,0.5:0.5", "--fraction-basis",
                    "volume",     "--sides",      "periodic",      "--out",
                    out.string(), "--quiet"};
    const testing::ProgramRun run = testing::run_program(SGMP_REFERENCE_EXE, options);
    BOOST_TEST_REQUIRE(run.exit_code == 0, run.stderr_text);
    const Pack pack = read_pack_file(out);
    BOOST_TEST_REQUIRE(pack.particles.size() == 600u);
    BOOST_TEST(*pack.metadata.get("sides") == "periodic");
    BOOST_TEST(*pack.metadata.get("species_counts") == "67,533");
    const double s = std::cbrt(18.0 * 0.63 / (3.141592653589793 * 600.0 * (1.0 / 9.0 + 1.0 / 9.0)));
    std::size_t large = 0;
    Container cell;
    cell.periodic = true;
    for (const Particle& p : pack.particles) {
        const double expected = p.species == 1 ? s / 2.0 : s / 4.0;
        BOOST_TEST(p.radius == expected, boost::test_tools::tolerance(1e-12));
        large += p.species == 1 ? 1 : 0;
        BOOST_TEST(p.center.x() >= cell.x_min);
        BOOST_TEST(p.center.x() < cell.x_max);
        BOOST_TEST(p.center.z() >= cell.z_min);
        BOOST_TEST(p.center.z() < cell.z_max);
    }
    BOOST_TEST(large == 67u);
    const double d = *pack.metadata.get_number("diameter");
    const OverlapCount overlaps = count_overlaps(pack.particles, cell, 0.0);
    BOOST_TEST(overlaps.max_pair < 0.01 * d);
    BOOST_TEST(overlaps.max_wall < 0.01 * d);  // the floor only
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
