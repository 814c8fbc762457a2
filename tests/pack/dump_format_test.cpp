#include "sgmp/pack/dump_format.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <sstream>

#include "sgmp/pack/lammps_data_format.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/xyz_format.hpp"

#include "test_support.hpp"

using namespace sgmp;
using sgmp::testing::input_error_of;

namespace {

const std::string kSnapshot0 =
    "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n"
    "-0.625 0.625\n-0.625 5\n-0.625 0.625\n"
    "ITEM: ATOMS type radius z y x id vx\n"
    "1 0.05 0.1 0.2 0.3 7 0\n1 0.05 0.4 0.5 0.6 8 0\n";
const std::string kSnapshot1 =
    "ITEM: TIMESTEP\n1000\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n"
    "-0.625 0.625\n-0.625 5\n-0.625 0.625\n"
    "ITEM: ATOMS id type x y z radius\n"
    "7 1 0.3 -0.575 0.1 0.05\n8 1 0.6 -0.475 0.4 0.05\n";

std::string read_error(const std::string& text) {
    return input_error_of([&] {
        std::istringstream in(text);
        read_dump_custom(in, "pour.dump");
    });
}

}  // namespace

BOOST_AUTO_TEST_SUITE(dump_format)

BOOST_AUTO_TEST_CASE(columns_are_found_by_label) {
    std::istringstream in(kSnapshot0);
    const Pack pack = read_dump_custom(in, "pour.dump");
    BOOST_TEST_REQUIRE(pack.particles.size() == 2u);
    BOOST_TEST(pack.particles[0].id == 7);
    BOOST_TEST(pack.particles[0].center.x() == 0.3);
    BOOST_TEST(pack.particles[0].center.y() == 0.2);
    BOOST_TEST(pack.particles[0].center.z() == 0.1);
    BOOST_TEST(pack.particles[0].radius == 0.05);
    BOOST_TEST(*pack.metadata.get("timestep") == "0");
    BOOST_TEST(*pack.metadata.get("dump_box") == "-0.625 0.625 -0.625 5 -0.625 0.625");
    // A simulation box is not a container: only recorded (stated_container.hpp).
    BOOST_TEST(!pack.metadata.contains("container"));
}

BOOST_AUTO_TEST_CASE(velocities_give_the_rms_speed) {
    // Speeds² 3² + 4² = 25 and 0: √(25/2), exactly as computed by hand.
    const std::string text =
        "ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n"
        "-1 1\n-1 1\n-1 1\nITEM: ATOMS id x y z radius vx vy vz\n"
        "1 0 0 0 0.1 3 0 -4\n2 0.5 0 0 0.1 0 0 0\n";
    std::istringstream in(text);
    const Pack pack = read_dump_custom(in, "v.dump");
    BOOST_TEST(*pack.metadata.get_number("velocity_rms") == std::sqrt(12.5));
    // One component alone is no speed: nothing recorded (kSnapshot0 has vx only).
    std::istringstream partial(kSnapshot0);
    BOOST_TEST(!read_dump_custom(partial, "p.dump").metadata.contains("velocity_rms"));
    BOOST_TEST(read_error("ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff ff\n"
                          "-1 1\n-1 1\n-1 1\nITEM: ATOMS id x y z radius vx vy vz\n"
                          "1 0 0 0 0.1 nan 0 0\n")
                   .find("pour.dump:10: column 'vx' holds 'nan'") == 0u);
}

BOOST_AUTO_TEST_CASE(the_last_snapshot_is_returned) {
    std::istringstream in(kSnapshot0 + kSnapshot1);
    const Pack pack = read_dump_custom(in, "pour.dump");
    BOOST_TEST(*pack.metadata.get("timestep") == "1000");
    BOOST_TEST(pack.particles[1].center.y() == -0.475);
}

BOOST_AUTO_TEST_CASE(a_last_snapshot_cut_short_leaves_the_last_complete_one) {
    // Cut after a whole line, inside a line, and inside the header of the snapshot.
    for (const std::size_t keep :
         {kSnapshot1.rfind("8 1"), kSnapshot1.rfind("-0.4"), kSnapshot1.find("ITEM: BOX") + 4}) {
        std::istringstream in(kSnapshot0 + kSnapshot1.substr(0, keep));
        const Pack pack = read_dump_custom(in, "pour.dump");
        BOOST_TEST(*pack.metadata.get("timestep") == "0");
        BOOST_TEST(pack.particles.size() == 2u);
    }
    // An error with lines after it is no truncation: the file is rejected.
    std::string bad_middle = kSnapshot1;
    bad_middle.replace(bad_middle.find("0.3 "), 3, "0.x");
    BOOST_TEST(read_error(kSnapshot0 + bad_middle) ==
               "pour.dump:21: column 'x' holds '0.x', which is not a number");
}

// Reliability finding 9: a second snapshot holding `nan` in its last, whole line was
// taken for one cut short: `convert` wrote the first snapshot with status 0.
BOOST_AUTO_TEST_CASE(a_corrupt_last_snapshot_is_refused_not_hidden) {
    std::string nan_last = kSnapshot1;
    nan_last.replace(nan_last.rfind("0.05"), 4, "nan");
    BOOST_TEST(read_error(kSnapshot0 + nan_last) ==
               "pour.dump:22: particle 8 has radius nan; a radius must be finite and > 0");
    std::string nan_coordinate = kSnapshot1;
    nan_coordinate.replace(nan_coordinate.rfind("0.6"), 3, "nan");
    BOOST_TEST(read_error(kSnapshot0 + nan_coordinate) ==
               "pour.dump:22: particle 8 has a coordinate that is not finite");
    // The same line without its line break is a line cut short: the first snapshot stands.
    std::istringstream cut(kSnapshot0 + nan_last.substr(0, nan_last.size() - 1));
    BOOST_TEST(*read_dump_custom(cut, "pour.dump").metadata.get("timestep") == "0");
    // The bin rule is the extended XYZ reader's (finding 12).
    std::string bin = kSnapshot1;
    bin.replace(bin.find("radius\n"), 7, "radius bin\n");
    bin.replace(bin.find("0.05\n8"), 6, "0.05 -5\n8");
    bin.replace(bin.rfind("0.05\n"), 5, "0.05 1\n");
    BOOST_TEST(read_error(bin) ==
               "pour.dump:10: column bin '-5' is not an integer in [0, 1000000]");
}

BOOST_AUTO_TEST_CASE(malformed_dumps_name_the_line_and_the_reason) {
    BOOST_TEST(read_error("") == "pour.dump: empty file: no snapshot");
    BOOST_TEST(read_error("hello\n") == "pour.dump:1: expected 'ITEM: TIMESTEP', found 'hello'");
    std::string missing_y = kSnapshot1;
    missing_y.replace(missing_y.find(" y "), 3, " q ");
    BOOST_TEST(read_error(missing_y) ==
               "pour.dump:9: ATOMS section lacks the 'y' column (scaled coordinates are not "
               "accepted)");
    std::string inverted = kSnapshot1;  // lo > hi, and NaN: accepted before
    inverted.replace(inverted.find("-0.625 5"), 8, "5 -0.625");
    BOOST_TEST(read_error(inverted) ==
               "pour.dump:7: box bounds '5 -0.625' must be finite with lo <= hi");
    std::string nan_box = kSnapshot1;
    nan_box.replace(nan_box.find("-0.625 5"), 8, "nan 5");
    BOOST_TEST(read_error(nan_box).find("pour.dump:7: box bounds") == 0u);
    std::string twice = kSnapshot1;  // x given twice: the last used to win
    twice.replace(twice.find(" y "), 3, " x ");
    BOOST_TEST(read_error(twice) == "pour.dump:9: ATOMS section names 'x' twice");
    std::string both_sizes = kSnapshot1;  // radius and diameter: radius used to win
    both_sizes.replace(both_sizes.find("z radius\n"), 9, "z radius diameter\n");
    BOOST_TEST(read_error(both_sizes) ==
               "pour.dump:9: ATOMS section holds both 'radius' and 'diameter': give one (which "
               "would count is not clear)");
    std::string no_radius = kSnapshot1;
    no_radius.replace(no_radius.find("radius"), 6, "mass");
    BOOST_TEST(read_error(no_radius) ==
               "pour.dump:9: ATOMS section lacks a 'radius' or 'diameter' column");
    std::string bad_number = kSnapshot1;
    bad_number.replace(bad_number.find("-0.475"), 6, "-0.4x5");
    BOOST_TEST(read_error(bad_number) ==
               "pour.dump:11: column 'y' holds '-0.4x5', which is not a number");
    const std::string truncated = kSnapshot1.substr(0, kSnapshot1.rfind("8 1"));
    BOOST_TEST(read_error(truncated) ==
               "pour.dump:10: file ends after 1 of 2 atom lines of timestep 1000");
    std::string short_line = kSnapshot1;
    short_line.replace(short_line.find(" 0.05\n8"), 5, "");
    BOOST_TEST(read_error(short_line) == "pour.dump:10: expected 6 columns as labelled, found 5");
    std::string nan_value = kSnapshot1;
    nan_value.replace(nan_value.find("0.3 "), 3, "nan");
    BOOST_TEST(read_error(nan_value) ==
               "pour.dump:10: particle 7 has a coordinate that is not finite");
    std::string bad_count = kSnapshot1;
    bad_count.replace(bad_count.find("\n2\n"), 3, "\n-2\n");
    BOOST_TEST(read_error(bad_count) ==
               "pour.dump:4: the number of atoms must be a non-negative integer, found '-2'");
}

BOOST_AUTO_TEST_CASE(a_claimed_count_allocates_nothing_before_its_lines_arrive) {
    // Counts the fuzzer found (1.5e9 atoms in a few hundred bytes) once ended in bad_alloc.
    for (const std::string count : {"1500000000", "9223372036854775807"}) {
        std::string claim = kSnapshot1;
        claim.replace(claim.find("\n2\n"), 3, "\n" + count + "\n");
        BOOST_TEST(read_error(claim) ==
                   "pour.dump:11: file ends after 2 of " + count + " atom lines of timestep 1000");
    }
}

BOOST_AUTO_TEST_CASE(a_box_periodic_on_every_axis_keeps_its_y_extent_in_every_output) {
    // A fully periodic box (pp pp pp, 0..6 on every axis) has no floor and no top: every writer
    // keeps y at 0..6, not the spheres' reach (y from 0.8 to 4.8 here).
    const std::string text =
        "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n"
        "0 6\n0 6\n0 6\nITEM: ATOMS id x y z radius\n1 1 1.3 1 0.5\n2 3 4.3 3 0.5\n";
    const sgmp::testing::TestDirectory directory("dump_format_periodic");
    sgmp::testing::write_text(directory.path() / "periodic.dump", text);
    const Pack pack = read_pack_file(directory.path() / "periodic.dump");  // as convert reads
    BOOST_TEST(*pack.metadata.get("periodic_y") == "0 6");
    BOOST_TEST(*pack.metadata.get("container_from") == "periodic box");

    std::ostringstream xyz;
    write_xyz(xyz, pack);
    BOOST_TEST(xyz.str().find("Lattice=\"6 0 0 0 6 0 0 0 6\" Origin=\"0 0 0\" pbc=\"T T T\"") !=
               std::string::npos);
    std::istringstream xyz_in(xyz.str());
    const Pack again = read_xyz(xyz_in, "periodic.xyz");
    BOOST_TEST(*again.metadata.get("periodic_y") == "0 6");

    std::ostringstream data;
    write_lammps_data(data, again);
    BOOST_TEST(data.str().find("0 6 ylo yhi") != std::string::npos);
    std::ostringstream dump;
    write_dump_custom(dump, again);
    BOOST_TEST(dump.str().find("ITEM: BOX BOUNDS pp pp pp") != std::string::npos);
    BOOST_TEST(dump.str().find("\n0 6\n0 6\n0 6\n") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
