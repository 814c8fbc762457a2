#include "sgmp/pack/stated_container.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "sgmp/pack/dump_format.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/pack_extent.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "test_support.hpp"

using namespace sgmp;
using sgmp::testing::input_error_of;

namespace {

/// The rule of the header key `container` (and --container, the manifest column), or "".
std::string parse_rule(const std::string& text) {
    try {
        (void)Container::parse(text);
    } catch (const ParameterError& error) {
        BOOST_TEST(error.name() == "container");
        BOOST_TEST(error.value() == "'" + text + "'");
        return error.rule();
    }
    return "";
}

// Two spheres of d = 1.25 in the box [0, 4] x [0, ...) x [0, 4], each `gap` from the faces
// it is nearest (x_min, z_min and the floor; x_max, z_max and the floor). With gap = 1/16
// every number is exact and gap / d = 0.0625 / 1.25 rounds to the double 0.05 itself: the
// clearance is exactly at the threshold.
constexpr double kRadius = 0.625;
constexpr double kGap = 0.0625;

Pack two_spheres(double gap) {
    Pack pack;
    const double near = kRadius + gap;
    const double far = 4.0 - kRadius - gap;
    pack.particles = {Particle{1, Vec3(near, kRadius + gap, near), kRadius, 0},
                      Particle{2, Vec3(far, kRadius + gap, far), kRadius, 0}};
    return pack;
}

const Container kBox{0.0, 4.0, 0.0, 4.0, 0.0};

}  // namespace

BOOST_AUTO_TEST_SUITE(stated_container)

BOOST_AUTO_TEST_CASE(the_one_parser_takes_five_finite_numbers_with_walls_in_order) {
    const Container c = Container::parse("-1 2 -3 4 -5");
    BOOST_TEST(c.x_min == -1.0);
    BOOST_TEST(c.x_max == 2.0);
    BOOST_TEST(c.z_min == -3.0);
    BOOST_TEST(c.z_max == 4.0);
    BOOST_TEST(c.floor == -5.0);
    BOOST_TEST(parse_rule("  -0.625 0.625 -0.625 0.625 -0.625 ") == "");
    const std::string five = "must be five finite numbers: x_min x_max z_min z_max floor";
    for (const char* bad : {"", "1 2 3 4", "0 1 0 1 0 7", "0 1 0 1 floor", "nan 1 0 1 0",
                            "0 inf 0 1 0", "0 1 0 1 1e999", "0 1 0 1 -1e999", "0,1,0,1,0"}) {
        BOOST_TEST(parse_rule(bad) == five, bad);
    }
    const std::string order =
        "must have x_min < x_max and z_min < z_max (x_min x_max z_min z_max floor)";
    for (const char* bad : {"1 1 0 1 0", "2 1 0 1 0", "0 1 1 1 0", "0 1 2 -2 0"}) {
        BOOST_TEST(parse_rule(bad) == order, bad);
    }
}

BOOST_AUTO_TEST_CASE(the_clearance_of_a_face_is_its_nearest_sphere_s) {
    const double d = 2.0 * kRadius;
    const BoxClearance at = largest_box_clearance(two_spheres(kGap).particles, kBox, d);
    BOOST_TEST(at.gap_over_d == kBoxReachOverD);  // exactly, not within a tolerance
    // 0.075 wider on each side (the foreign pour): the clearance grows by 0.075 / d.
    const Container wider{-0.075, 4.075, -0.075, 4.075, 0.0};
    const BoxClearance w = largest_box_clearance(two_spheres(kGap).particles, wider, d);
    BOOST_TEST(w.gap_over_d == (kGap + 0.075) / d, boost::test_tools::tolerance(1e-12));
    // Only the floor far: it is named.
    const Container deep{0.0, 4.0, 0.0, 4.0, -1.0};
    const BoxClearance f = largest_box_clearance(two_spheres(kGap).particles, deep, d);
    BOOST_TEST(f.face == "floor");
    BOOST_TEST(f.gap_over_d == (kGap + 1.0) / d, boost::test_tools::tolerance(1e-12));
    // Periodic axes are not walls: only the floor counts.
    Container periodic = wider;
    periodic.periodic = true;
    const BoxClearance p = largest_box_clearance(two_spheres(kGap).particles, periodic, d);
    BOOST_TEST(p.face == "floor");
    BOOST_TEST(p.gap_over_d == kBoxReachOverD);
}

BOOST_AUTO_TEST_CASE(a_box_is_taken_only_when_the_spheres_reach_it) {
    // Exactly at the threshold: taken, and the pack says so.
    Pack at = two_spheres(kGap);
    settle_container(at, std::nullopt, kBox, "at.dump");
    BOOST_TEST(at.metadata.get("container").value_or("") == "0 4 0 4 0");
    BOOST_TEST(at.metadata.get("container_from").value_or("") == "box");
    // One step beyond it, at the floor alone: refused, naming the file, gap and option.
    Pack beyond = two_spheres(kGap);
    for (Particle& p : beyond.particles) {
        p.center.y() = std::nextafter(p.center.y(), 1.0);
    }
    const std::string error =
        input_error_of([&] { settle_container(beyond, std::nullopt, kBox, "beyond.dump"); });
    BOOST_TEST(error.find("beyond.dump: no container stated, and the spheres keep 0.05 d of "
                          "clearance beyond contact from the box's floor (more than 0.05 d)") == 0U,
               error);
    BOOST_TEST(error.find("--container \"x_min x_max z_min z_max floor\"") != std::string::npos);
    BOOST_TEST(error.find('\n') == std::string::npos);
    BOOST_TEST(!beyond.metadata.contains("container"));
    // 0.075 wider: refused at 0.11 d, and stated, the walls are the pack's.
    const Container wider{-0.075, 4.075, -0.075, 4.075, 0.0};
    Pack far = two_spheres(kGap);
    BOOST_TEST(input_error_of([&] {
                   settle_container(far, std::nullopt, wider, "w.dump");
               }).find("keep 0.11 d of clearance beyond contact from the box's") !=
               std::string::npos);
    settle_container(far, StatedContainer{kBox, "--container"}, wider, "w.dump");
    BOOST_TEST(far.metadata.get("container").value_or("") == "0 4 0 4 0");
    BOOST_TEST(far.metadata.get("container_from").value_or("") == "--container");
    // A box without width is no container either.
    Pack flat = two_spheres(kGap);
    BOOST_TEST(input_error_of([&] {
                   settle_container(flat, std::nullopt, Container{1, 1, 0, 4, 0}, "f.dump");
               }).find("f.dump: no container stated, and the box '1 1 0 4 0'") == 0U);
    // Periodic sides: only the floor must be reached.
    Pack periodic = two_spheres(kGap);
    periodic.metadata.set("sides", "periodic");
    settle_container(periodic, std::nullopt, wider, "p.dump");
    BOOST_TEST(periodic.metadata.get("container").value_or("") == "-0.075 4.075 -0.075 4.075 0");
}

BOOST_AUTO_TEST_CASE(a_statement_must_agree_with_the_file_and_hold_every_centre) {
    Pack own = two_spheres(kGap);
    own.metadata.set("container", "0 4 0 4 0");
    // The file's own container stands without a statement, and is not re-recorded.
    settle_container(own, std::nullopt, std::nullopt, "own.xyz");
    BOOST_TEST(!own.metadata.contains("container_from"));
    // The same walls stated (to rounding) agree; others contradict it, in one line.
    settle_container(own, StatedContainer{Container{0, 4.000000000000001, 0, 4, 0}, "m.csv:3"},
                     std::nullopt, "own.xyz");
    const std::string contradiction = input_error_of([&] {
        settle_container(own, StatedContainer{Container{0, 5, 0, 4, 0}, "manifest m.csv:3"},
                         std::nullopt, "own.xyz");
    });
    BOOST_TEST(contradiction ==
               "own.xyz: manifest m.csv:3 container '0 5 0 4 0' contradicts the "
               "file's own container '0 4 0 4 0' (x_min x_max z_min z_max "
               "floor)");
    // A container that leaves out a centre names the sphere.
    Pack pack = two_spheres(kGap);
    const std::string outside = input_error_of([&] {
        settle_container(pack, StatedContainer{Container{0, 3, 0, 4, 0}, "--container"},
                         std::nullopt, "p.dump");
    });
    BOOST_TEST(outside ==
               "p.dump: sphere id 2 at (3.3125, 0.6875, 3.3125) lies outside the "
               "container '0 3 0 4 0' (from --container; x_min x_max z_min z_max "
               "floor)");
    BOOST_TEST(!first_centre_outside(pack.particles, Container{0, 4, 0, 4, 0.6875}).has_value());
    BOOST_TEST(first_centre_outside(pack.particles, Container{0, 4, 0, 4, 0.7}).value_or(9) == 0U);
    Container periodic{1, 2, 1, 2, 0};
    periodic.periodic = true;  // x and z wrap: only the floor holds centres
    BOOST_TEST(!first_centre_outside(pack.particles, periodic).has_value());
}

// Files: a dump's or data file's box is taken only when reached; `sgmp convert`'s dumps
// and data files carry their walls, which read back.
BOOST_AUTO_TEST_CASE(dump_and_data_files_state_or_reach_their_walls) {
    const sgmp::testing::TestDirectory scratch("stated_container");
    const std::filesystem::path dir = scratch.path();
    const auto dump = [](const std::string& flags, double wall) {
        std::ostringstream text;
        text << "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS " << flags << "\n"
             << 0.0 - wall << " " << 4.0 + wall << "\n0 4\n"
             << 0.0 - wall << " " << 4.0 + wall << "\nITEM: ATOMS id x y z radius\n"
             << "1 0.6875 0.6875 0.6875 0.625\n2 3.3125 0.6875 3.3125 0.625\n";
        return text.str();
    };
    std::ofstream(dir / "at.dump") << dump("ff ff ff", 0.0);
    BOOST_TEST(read_pack_file(dir / "at.dump").metadata.get("container").value_or("") ==
               "0 4 0 4 0");
    std::ofstream(dir / "wide.dump") << dump("ff ff ff", 0.075);
    BOOST_TEST(input_error_of([&] {
                   read_pack_file(dir / "wide.dump");
               }).find("wide.dump: no container stated, and the spheres keep 0.11 d") !=
               std::string::npos);
    ReadOptions stated;
    stated.container = StatedContainer{Container{0, 4, 0, 4, 0}, "--container"};
    BOOST_TEST(read_pack_file(dir / "wide.dump", stated)
                   .pack.metadata.get("container_from")
                   .value_or("") == "--container");
    // The walls written after the flags are the file's own: read, and checked.
    std::ofstream(dir / "own.dump") << dump("ff ff ff container 0 4 0 4 0", 0.075);
    BOOST_TEST(read_pack_file(dir / "own.dump").metadata.get("container").value_or("") ==
               "0 4 0 4 0");
    std::ofstream(dir / "bad.dump") << dump("ff ff ff container 0 4 0 4", 0.075);
    BOOST_TEST(input_error_of([&] {
                   read_pack_file(dir / "bad.dump");
               }).find("must be followed by five numbers") != std::string::npos);
    // A data file: the same rule on its xlo..zhi box.
    const auto data = [](double wall) {
        std::ostringstream text;
        text << "LAMMPS data file\n\n2 atoms\n1 atom types\n\n"
             << 0.0 - wall << " " << 4.0 + wall << " xlo xhi\n0 4 ylo yhi\n"
             << 0.0 - wall << " " << 4.0 + wall << " zlo zhi\n\nAtoms # sphere\n\n"
             << "1 1 1.25 1 0.6875 0.6875 0.6875\n2 1 1.25 1 3.3125 0.6875 3.3125\n";
        return text.str();
    };
    std::ofstream(dir / "at.data") << data(0.0);
    BOOST_TEST(read_pack_file(dir / "at.data").metadata.get("container_from").value_or("") ==
               "box");
    std::ofstream(dir / "wide.data") << data(0.075);
    BOOST_TEST(input_error_of([&] {
                   read_pack_file(dir / "wide.data");
               }).find("keep 0.11 d of clearance") != std::string::npos);
    // Written by the pack library (as `sgmp convert` does), a far container travels along.
    Pack column;
    column.metadata.set("container", "-0.625 0.625 -0.625 0.625 -0.625");
    column.particles = {Particle{1, Vec3(0, -0.575, 0), 0.05, 0},
                        Particle{2, Vec3(0, -0.475, 0), 0.05, 0}};
    for (const char* name : {"column.dump", "column.data"}) {
        write_pack_as(dir / name, column, *format_from_extension(dir / name), WriteOptions{true});
        const Pack back = read_pack_file(dir / name);
        BOOST_TEST(
            back.metadata.get("container").value_or("") == "-0.625 0.625 -0.625 0.625 -0.625",
            name);
    }
}

BOOST_AUTO_TEST_SUITE_END()
