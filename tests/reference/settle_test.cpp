// A real settle with LIGGGHTS: a relaxed 300-sphere SGMP pack, settled at mu = 0.01 by
// `sgmp-reference settle` (a few seconds).
#include <boost/test/unit_test.hpp>
#include <filesystem>

#include "run_program.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/pack_overlaps.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"

namespace fs = std::filesystem;
using namespace sgmp;
using namespace sgmp::reference;

namespace {

testing::ProgramRun run_reference(std::vector<std::string> args) {
    testing::ProgramOptions options;
    options.args = std::move(args);
    return testing::run_program(SGMP_REFERENCE_EXE, options);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(liggghts_settle)

BOOST_AUTO_TEST_CASE(a_relaxed_sgmp_pack_of_300_settles_from_where_it_is) {
    const fs::path dir = testing::fresh_directory("sgmp-settle-test");
    engine::PackRequest request;
    request.count = 300;
    request.arrangement = engine::Arrangement::LooseRandom;
    request.relax.mode = engine::RelaxMode::Frictionless;
    const Pack start = engine::make_pack(request);
    const fs::path start_file = dir / "start.xyz";
    write_pack_file(start_file, start, false);
    const fs::path out = dir / "settled.xyz";
    const auto run = run_reference(
        {"settle", start_file.string(), "--friction", "0.01", "--out", out.string(), "--quiet"});
    BOOST_TEST_INFO(run.stderr_text);
    BOOST_TEST_REQUIRE(run.exit_code == 0);
    const Pack pack = read_pack_file(out);
    BOOST_TEST_REQUIRE(pack.particles.size() == 300u);
    const double d = *start.metadata.get_number("diameter");
    // The pour's own tolerances (pour_test.cpp): overlaps and wall penetrations below 1 % of d.
    const OverlapCount overlaps = count_overlaps(pack.particles, Container{}, 0.0);
    BOOST_TEST(overlaps.max_wall < 0.01 * d);
    BOOST_TEST(overlaps.max_pair < 0.01 * d);
    BOOST_TEST(*pack.metadata.get_number("settling_measure") <
               *pack.metadata.get_number("settle_threshold"));
    BOOST_TEST(std::abs(*pack.metadata.get_number("diameter") - d) <= 1e-12 * d);
    BOOST_TEST(pack.metadata.get("start").value_or("") == "pack");
    BOOST_TEST(pack.metadata.get("start_pack").value_or("") == "start.xyz");
    BOOST_TEST(pack.metadata.get("start_generator").value_or("") == "sgmp");
    BOOST_TEST(pack.metadata.get_number("steps").value_or(0) > 0.0);
    BOOST_TEST(pack.metadata.contains("wall_seconds"));
    // Settling a relaxed pack keeps it a dense random pack: the control volume's φ stays
    // within 0.03 of where it started (measured 0.6226 → 0.6265).
    const double before = packing_fraction(start, control_volume());
    const double after = packing_fraction(pack, control_volume());
    BOOST_TEST(std::abs(after - before) < 0.03);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_stored_dem_pour_settles_again_with_stiffer_contacts) {
    // A DEM pour keeps its soft wall contacts (up to 0.006 d): settle must start from it.
    const fs::path dir = testing::fresh_directory("sgmp-settle-dem");
    const fs::path start_file = fs::path(SGMP_REFERENCE_DATA) / "n0150-mu0.5-seed1.xyz.gz";
    const Pack start = read_pack_file(start_file);
    const double d = *start.metadata.get_number("diameter");
    BOOST_TEST_REQUIRE(count_overlaps(start.particles, Container{}, 0.0).max_wall > 1e-6 * d);
    const fs::path out = dir / "stiff.xyz";
    const auto run =
        run_reference({"settle", start_file.string(), "--friction", "0.5", "--youngs-modulus",
                       "1.6e10", "--out", out.string(), "--quiet"});
    BOOST_TEST_INFO(run.stderr_text);
    BOOST_TEST_REQUIRE(run.exit_code == 0);
    const Pack pack = read_pack_file(out);
    BOOST_TEST(*pack.metadata.get_number("youngs_modulus_pa") == 1.6e10);
    BOOST_TEST(pack.metadata.get("start_generator").value_or("") == "liggghts");
    // 16× stiffer Hertz contacts overlap 16^(2/3) ≈ 6.3× less: the deepest pair and wall
    // overlaps fall (the stored pour's are about 0.004 d; bound: half of the start's).
    const OverlapCount before = count_overlaps(start.particles, Container{}, 0.0);
    const OverlapCount after = count_overlaps(pack.particles, Container{}, 0.0);
    BOOST_TEST(after.max_pair < 0.5 * before.max_pair);
    BOOST_TEST(after.max_wall < 0.5 * before.max_wall);
    // A settled frictional bed does not rearrange: φ of the control volume moves by less
    // than 0.01 (the seed spread of φ at N = 150 is about 0.01).
    BOOST_TEST(std::abs(packing_fraction(pack, control_volume()) -
                        packing_fraction(start, control_volume())) < 0.01);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(settle_refuses_a_start_deeper_through_a_wall_than_a_settled_pour) {
    const fs::path dir = testing::fresh_directory("sgmp-settle-deep");
    Pack start = read_pack_file(fs::path(SGMP_REFERENCE_DATA) / "n0150-mu0.5-seed1.xyz.gz");
    const double r = start.particles.front().radius;
    start.particles[4].center.x() = Container{}.x_min + r - 0.1 * 2.0 * r;  // 0.1 d through
    const fs::path start_file = dir / "deep.xyz";
    write_pack_file(start_file, start, false);
    const std::string out = (dir / "out.xyz").string();
    const auto run =
        run_reference({"settle", start_file.string(), "--friction", "0.5", "--out", out});
    BOOST_TEST(run.exit_code == 1);
    BOOST_TEST(run.stderr_text.find("sphere 5 reaches 0.1 d through a wall or the floor (at most "
                                    "0.05 d)") != std::string::npos,
               run.stderr_text);
    BOOST_TEST(!fs::exists(out));
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(settle_refuses_unequal_spheres_and_a_missing_friction) {
    const fs::path dir = testing::fresh_directory("sgmp-settle-refusals");
    engine::PackRequest request;
    request.count = 60;
    request.size_modes = {{1.0, 0.5}, {0.5, 0.5}};
    const fs::path start_file = dir / "bimodal.xyz";
    write_pack_file(start_file, engine::make_pack(request), false);
    const std::string out = (dir / "out.xyz").string();
    const auto unequal =
        run_reference({"settle", start_file.string(), "--friction", "0.5", "--out", out});
    BOOST_TEST(unequal.exit_code == 2);
    BOOST_TEST(unequal.stderr_text.find("sgmp-reference: settle ") == 0u);
    BOOST_TEST(unequal.stderr_text.find("different radii") != std::string::npos);
    const auto no_friction = run_reference({"settle", start_file.string(), "--out", out});
    BOOST_TEST(no_friction.exit_code == 2);
    BOOST_TEST(!fs::exists(out));
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
