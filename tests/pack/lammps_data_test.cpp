// The LAMMPS data reader keeps the extended XYZ reader's header and bin rules (reliability
// finding 11): one concept in one place (detail::HeaderKeys, detail::parse_bin).
#include <boost/test/unit_test.hpp>
#include <sstream>

#include "sgmp/pack/lammps_data_format.hpp"
#include "sgmp/pack/xyz_format.hpp"
#include "test_support.hpp"

using namespace sgmp;
using sgmp::testing::input_error_of;

namespace {

/// A data file of two atoms; `header` holds comment lines, `tags` the two atoms' comments.
std::string data_file(const std::string& header, const std::string& tag1 = "bin 0 species 1",
                      const std::string& tag2 = "bin 1 species 2") {
    return "LAMMPS data file (atom_style sphere)\n" + header +
           "\n2 atoms\n2 atom types\n\n-1 1 xlo xhi\n-1 1 ylo yhi\n-1 1 zlo zhi\n\n"
           "Atoms # sphere\n\n1 1 0.2 2500 0 -0.9 0 # " +
           tag1 + "\n2 2 0.1 2500 0.5 -0.95 0 # " + tag2 + "\n";
}

std::string read_error(const std::string& text) {
    return input_error_of([&] {
        std::istringstream in(text);
        read_lammps_data(in, "p.data");
    });
}

}  // namespace

BOOST_AUTO_TEST_SUITE(lammps_data)

BOOST_AUTO_TEST_CASE(a_blend_reads_back_and_converts_to_an_xyz_our_reader_takes) {
    std::istringstream in(data_file("# container=-1 1 -1 1 -1\n# seed=3\n# note=caf\xc3\xa9"));
    const Pack pack = read_lammps_data(in, "p.data");
    BOOST_TEST_REQUIRE(pack.particles.size() == 2u);
    BOOST_TEST(pack.particles[1].species == 2);
    BOOST_TEST(pack.particles[1].color == 1);
    std::ostringstream xyz;
    write_xyz(xyz, pack);
    std::istringstream back(xyz.str());
    BOOST_TEST(read_xyz(back, "p.xyz").particles.at(1).species == 2);
}

BOOST_AUTO_TEST_CASE(the_header_rule_is_the_xyz_readers) {
    // An escape sequence in a comment was kept, and `sgmp-compare header` printed it raw.
    BOOST_TEST(read_error(data_file("# note=\x1b]0;owned\x07")) ==
               "p.data:2: header entry 'note=\\x1b]0;owned\\x07' holds a control character");
    // A key given twice: the last one won.
    BOOST_TEST(read_error(data_file("# seed=1\n# seed=2")) ==
               "p.data:3: header key 'seed' appears twice");
    // A Latin-1 byte broke the JSON outputs after a whole measure (finding 14).
    BOOST_TEST(read_error(data_file("# note=caf\xe9")) ==
               "p.data:2: header entry 'note=caf\\xe9' is not UTF-8 (a Latin-1 byte?): header "
               "text must be UTF-8");
}

BOOST_AUTO_TEST_CASE(a_blend_tags_every_atom) {
    // One atom without its species was written by `convert` as species_id 0, which the
    // extended XYZ reader refuses.
    BOOST_TEST(read_error(data_file("", "bin 0 species 1", "bin 1")) ==
               "p.data:13: atom 2 lacks the species tag ('# bin B species S') of the atom of "
               "line 12: a blend tags every atom, a single size none");
    BOOST_TEST(read_error(data_file("", "bin 0", "bin 1 species 2")) ==
               "p.data:13: atom 2 has a species tag and the atom of line 12 has none: a blend "
               "tags every atom, a single size none");
    std::istringstream single(data_file("", "bin 0", "bin 1"));
    BOOST_TEST(read_lammps_data(single, "p.data").particles.at(1).species == 0);
}

BOOST_AUTO_TEST_CASE(bin_keeps_the_readers_one_range) {
    // Out of range was silently dropped to bin 0 (4294967297 would have been 1 in xyz).
    BOOST_TEST(read_error(data_file("", "bin 4294967297 species 1")) ==
               "p.data:12: bin '4294967297' is not an integer in [0, 1000000]");
    BOOST_TEST(read_error(data_file("", "bin 0 species 1", "bin -5 species 2")) ==
               "p.data:13: bin '-5' is not an integer in [0, 1000000]");
}

BOOST_AUTO_TEST_SUITE_END()
