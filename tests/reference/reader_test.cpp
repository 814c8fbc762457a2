// The pack library's dump reader on LIGGGHTS output: a real dump (cut to four spheres)
// and malformed variants. Errors must name file:line and the reason.
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <string>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/pack_file.hpp"

namespace {

std::string fixture(const std::string& name) {
    return (std::filesystem::path(SGMP_SOURCE_DIR) / "tests/reference/fixtures" / name).string();
}

/// The message of the InputError reading `name` throws ("" when none is thrown).
std::string error_of(const std::string& name) {
    try {
        sgmp::read_pack_file(fixture(name));
    } catch (const sgmp::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(liggghts_dump_reader)

BOOST_AUTO_TEST_CASE(reads_the_last_snapshot_with_every_digit) {
    // Four spheres of a pour do not reach its box: the pour's walls are stated, as the
    // reference reads its own result (a simulation box is not a container).
    BOOST_TEST(error_of("liggghts_two_snapshots.dump").find("no container stated") !=
               std::string::npos);
    sgmp::ReadOptions walls;
    walls.container = sgmp::StatedContainer{sgmp::Container{}, "the pour's walls"};
    const sgmp::Pack pack =
        sgmp::read_pack_file(fixture("liggghts_two_snapshots.dump"), walls).pack;
    BOOST_TEST_REQUIRE(pack.particles.size() == 4u);
    BOOST_TEST(pack.metadata.get("container_from").value_or("") == "the pour's walls");
    BOOST_TEST(*pack.metadata.get("timestep") == "14385");
    // The first atom line of the last snapshot, written with %.17g, reads back exactly.
    BOOST_TEST(pack.particles[0].id == 123);
    BOOST_TEST(pack.particles[0].center.x() == -0.47168132492391152);
    BOOST_TEST(pack.particles[0].center.y() == -0.48075586893312094);
    BOOST_TEST(pack.particles[0].center.z() == -0.47977486999262464);
    BOOST_TEST(pack.particles[0].radius == 0.14435349789759477);
}

BOOST_AUTO_TEST_CASE(a_missing_column_is_named) {
    BOOST_TEST(error_of("missing_column.dump") ==
               fixture("missing_column.dump") +
                   ":9: ATOMS section lacks the 'z' column (scaled coordinates are not accepted)");
}

BOOST_AUTO_TEST_CASE(a_non_numeric_value_is_named_with_its_line) {
    BOOST_TEST(error_of("non_numeric.dump") ==
               fixture("non_numeric.dump") + ":12: column 'y' holds '0.4O', which is not a number");
}

BOOST_AUTO_TEST_CASE(a_truncated_snapshot_is_reported) {
    BOOST_TEST(error_of("truncated.dump") ==
               fixture("truncated.dump") +
                   ":12: file ends after 3 of 4 atom lines of timestep 14385");
}

BOOST_AUTO_TEST_CASE(a_nan_coordinate_is_rejected) {
    BOOST_TEST(error_of("nan_coordinate.dump") ==
               fixture("nan_coordinate.dump") +
                   ":11: particle 131 has a coordinate that is not finite");
}

BOOST_AUTO_TEST_SUITE_END()
