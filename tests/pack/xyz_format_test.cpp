#include "sgmp/pack/xyz_format.hpp"

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sgmp/pack/pack_extent.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/pack_format.hpp"

#include "sgmp/pack/line_reader.hpp"
#include "sgmp/pack/random.hpp"
#include "test_support.hpp"

using namespace sgmp;
using sgmp::testing::input_error_of;

namespace {

Pack random_pack(std::uint64_t seed, int count) {
    Random random(seed);
    Pack pack;
    pack.metadata.set("generator", "sgmp");
    pack.metadata.set_integer("seed", static_cast<long long>(seed));
    pack.metadata.set("container", "-0.625 0.625 -0.625 0.625 -0.625");
    pack.metadata.set_number("diameter", 0.1533);
    for (int i = 0; i < count; ++i) {
        pack.particles.push_back(Particle{
            i + 1, Vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)),
            random.uniform(0.01, 0.1), static_cast<int>(i % 10)});
    }
    return pack;
}

std::string read_error(const std::string& text) {
    return input_error_of([&] {
        std::istringstream in(text);
        read_xyz(in, "pack.xyz");
    });
}

const std::string kHeader = "Properties=id:I:1:pos:R:3:radius:R:1:color:I:1 pbc=\"F F F\"\n";

}  // namespace

BOOST_AUTO_TEST_SUITE(xyz_format)

BOOST_AUTO_TEST_CASE(round_trip_is_bit_identical) {
    const Pack pack = random_pack(7, 200);
    std::ostringstream out;
    write_xyz(out, pack);
    std::istringstream in(out.str());
    const Pack back = read_xyz(in, "memory");
    BOOST_TEST_REQUIRE(back.particles.size() == pack.particles.size());
    for (std::size_t i = 0; i < pack.particles.size(); ++i) {
        BOOST_TEST(back.particles[i].id == pack.particles[i].id);
        BOOST_TEST((back.particles[i].center.array() == pack.particles[i].center.array()).all());
        BOOST_TEST(back.particles[i].radius == pack.particles[i].radius);
        BOOST_TEST(back.particles[i].color == pack.particles[i].color);
    }
    BOOST_TEST(back.metadata.entries() == pack.metadata.entries());
    // Writing what was read gives the same bytes.
    std::ostringstream again;
    write_xyz(again, back);
    BOOST_TEST(again.str() == out.str());
}

BOOST_AUTO_TEST_CASE(species_travel_with_blends_only) {
    Pack pack = random_pack(3, 30);
    std::ostringstream single;
    write_xyz(single, pack);
    BOOST_TEST(single.str().find("species") == std::string::npos);  // one species: no column
    for (std::size_t i = 0; i < pack.particles.size(); ++i) {
        pack.particles[i].species = 1 + static_cast<int>(i % 3);
    }
    std::ostringstream out;
    write_xyz(out, pack);
    BOOST_TEST(out.str().find("Properties=id:I:1:pos:R:3:radius:R:1:bin:I:1:species_id:I:1 ") !=
               std::string::npos);
    std::istringstream in(out.str());
    const Pack back = read_xyz(in, "memory");
    for (std::size_t i = 0; i < pack.particles.size(); ++i) {
        BOOST_TEST(back.particles[i].species == pack.particles[i].species);
    }
    const std::string bad =
        "1\nProperties=id:I:1:pos:R:3:radius:R:1:species_id:I:1\n1 0 0 0 0.1 0\n";
    BOOST_TEST(read_error(bad) == "pack.xyz:3: species_id 0 is not in [1, 1000000]");
}

BOOST_AUTO_TEST_CASE(quoted_values_and_columns_in_any_order) {
    const std::string text =
        "2\nProperties=pos:R:3:species:S:1:diameter:R:1:id:I:1 note=\"two words\" x=1\n"
        "0 0 0 Fe 0.2 5\n1 1 1 Fe 0.4 9\n";
    std::istringstream in(text);
    const Pack pack = read_xyz(in, "ase.xyz");
    BOOST_TEST(pack.particles.size() == 2u);
    BOOST_TEST(pack.particles[1].id == 9);
    BOOST_TEST(pack.particles[1].radius == 0.2);
    BOOST_TEST(pack.particles[1].color == 0);
    BOOST_TEST(*pack.metadata.get("note") == "two words");
}

BOOST_AUTO_TEST_CASE(malformed_files_name_the_line_and_the_reason) {
    BOOST_TEST(read_error("") == "pack.xyz: empty file: expected the particle count on line 1");
    BOOST_TEST(read_error("two\n") == "pack.xyz:1: expected the particle count, found 'two'");
    BOOST_TEST(read_error("1\n") == "pack.xyz:1: file ends before the header line");
    BOOST_TEST(read_error("1\npbc=\"F F F\"\n0 0 0 0 1 0\n") ==
               "pack.xyz:2: header lacks Properties=...");
    BOOST_TEST(read_error("1\nProperties=id:I:1:radius:R:1\n1 0.1\n") ==
               "pack.xyz:2: Properties lacks the 'pos' column");
    BOOST_TEST(read_error("2\n" + kHeader + "1 0 0 0 0.1 0\n") ==
               "pack.xyz:3: file ends after 1 of 2 particle lines");
    BOOST_TEST(read_error("1\n" + kHeader + "1 0 0 0 0.1 0\n2 0 0 0 0.1 0\n") ==
               "pack.xyz:4: expected the particle count of frame 2 (or the end of the file), "
               "found '2 0 0 0 0.1 0'; are there more particle lines than the frame's count?");
    BOOST_TEST(read_error("1\n" + kHeader + "1 0 zero 0 0.1 0\n") ==
               "pack.xyz:3: coordinate 'zero' is not a number");
    BOOST_TEST(read_error("1\n" + kHeader + "1 0 0 0 0.1\n") ==
               "pack.xyz:3: expected 6 columns, found 5");
    BOOST_TEST(read_error("1\n" + kHeader + "1 nan 0 0 0.1 0\n") ==
               "pack.xyz:3: particle 1 has a coordinate that is not finite");
    BOOST_TEST(read_error("1\n" + kHeader + "1 0 inf 0 0.1 0\n") ==
               "pack.xyz:3: particle 1 has a coordinate that is not finite");
    BOOST_TEST(read_error("1\n" + kHeader + "1 0 0 0 -0.1 0\n") ==
               "pack.xyz:3: particle 1 has radius -0.1; a radius must be finite and > 0");
    BOOST_TEST(read_error("2\n" + kHeader + "4 0 0 0 0.1 0\n4 1 0 0 0.1 0\n") ==
               "pack.xyz:4: id 4 repeats the id of line 3");
    BOOST_TEST(read_error("1\nProperties=id:I:1 \"x\n") ==
               "pack.xyz:2: expected key=value or a bare key in the header, found '\"x'");
}

BOOST_AUTO_TEST_CASE(a_cell_the_reader_skips_must_still_be_a_cell) {
    // Lattice and Origin are derived on writing, but ASE and OVITO read them: a NaN, a
    // wrong count or a negative side is refused, not passed on.
    const std::string props = "Properties=id:I:1:pos:R:3:radius:R:1:bin:I:1";
    const std::string line = "1 0 0 0 0.1 0\n";
    BOOST_TEST(read_error("1\n" + props + " Lattice=\"nan 0 0 0 1 0 0 0 1\"\n" + line) ==
               "pack.xyz:2: Lattice=\"nan 0 0 0 1 0 0 0 1\" must be 9 finite numbers, its "
               "diagonal >= 0");
    BOOST_TEST(read_error("1\n" + props + " Lattice=\"1 0 0 0 -1 0 0 0 1\"\n" + line) ==
               "pack.xyz:2: Lattice=\"1 0 0 0 -1 0 0 0 1\" must be 9 finite numbers, its "
               "diagonal >= 0");
    BOOST_TEST(read_error("1\n" + props + " Origin=\"0 0\"\n" + line) ==
               "pack.xyz:2: Origin=\"0 0\" must be 3 finite numbers");
    BOOST_TEST(read_error("1\n" + props + " Origin=\"0 inf 0\"\n" + line) ==
               "pack.xyz:2: Origin=\"0 inf 0\" must be 3 finite numbers");
    std::istringstream good(
        "1\n" + props + " Lattice=\"1.25 0 0 0 2 0 0 0 1.25\" Origin=\"-0.625 -0.625 -0.625\"\n" +
        line);
    BOOST_TEST(read_xyz(good, "pack.xyz").particles.size() == 1u);
}

BOOST_AUTO_TEST_CASE(column_counts_cannot_overflow_the_line_width) {
    // A count near 2^32 once wrapped the width, so a line passed the width check while the
    // position column pointed past its fields.
    const std::string rule =
        "a count must be a positive integer and all entries together at most 10000 columns";
    BOOST_TEST(read_error("1\nProperties=foo:R:5:pos:R:3:radius:R:1:bar:R:4294967287\n\n") ==
               "pack.xyz:2: Properties entry 'bar' has count '4294967287'; " + rule);
    BOOST_TEST(read_error("1\nProperties=pos:R:3:radius:R:1:bar:R:9223372036854775807\n\n") ==
               "pack.xyz:2: Properties entry 'bar' has count '9223372036854775807'; " + rule);
    BOOST_TEST(read_error("1\nProperties=pos:R:3:radius:R:1:a:R:9990:b:R:7\n\n") ==
               "pack.xyz:2: Properties entry 'b' has count '7'; " + rule);
    // 10000 columns in all is still accepted.
    std::string line = "0 0 0 0.1";
    for (int i = 0; i < 9996; ++i) {
        line += " 1";
    }
    std::istringstream in("1\nProperties=pos:R:3:radius:R:1:a:R:9996\n" + line + "\n");
    BOOST_TEST(read_xyz(in, "pack.xyz").particles.size() == 1u);
}

// Readers have stated limits (line_reader.hpp, xyz_format.cpp): a line of 16 MiB, 10,000
// header keys, each key once. Memory stays bounded on an endless line (/dev/zero, a gzip
// holding one 1 GB line) and on a header of millions of keys.
BOOST_AUTO_TEST_CASE(readers_refuse_what_would_allocate_without_bound) {
    const std::string endless(sgmp::kMaxLineBytes + 10, '0');
    BOOST_TEST(read_error(endless) ==
               "pack.xyz:1: line longer than 16777216 bytes (the readers' limit)");
    BOOST_TEST(read_error("1\n" + endless) ==
               "pack.xyz:2: line longer than 16777216 bytes (the readers' limit)");
    std::string keys;
    for (int k = 0; k < 10001; ++k) {
        keys += "k" + std::to_string(k) + "=1 ";
    }
    BOOST_TEST(read_error("1\n" + keys + kHeader + "1 0 0 0 0.05 0\n") ==
               "pack.xyz:2: more than 10000 header keys (the readers' limit)");
    BOOST_TEST(read_error("1\nseed=1 seed=2 " + kHeader + "1 0 0 0 0.05 0\n") ==
               "pack.xyz:2: header key 'seed' appears twice");
    // ESC and BEL in a value (terminal escapes; `header` printed them raw, `convert` copied
    // them): refused, the bytes escaped in the message.
    BOOST_TEST(read_error("1\nnote=\x1b[31mred\x07 " + kHeader + "1 0 0 0 0.05 0\n") ==
               "pack.xyz:2: header entry 'note=\\x1b[31mred\\x07' holds a control character");
    // Ambiguous columns: a repeated name, radius beside diameter, bin beside color.
    BOOST_TEST(
        read_error("1\nProperties=id:I:1:pos:R:3:radius:R:1:pos:R:3\n1 0 0 0 0.05 1 1 1\n") ==
        "pack.xyz:2: Properties names 'pos' twice");
    BOOST_TEST(
        read_error("1\nProperties=id:I:1:pos:R:3:radius:R:1:diameter:R:1\n1 0 0 0 0.05 0.2\n")
            .find("pack.xyz:2: Properties holds both 'radius' and 'diameter'") == 0u);
    BOOST_TEST(
        read_error(
            "1\nProperties=id:I:1:pos:R:3:radius:R:1:bin:I:1:color:I:1\n1 0 0 0 0.05 1 2\n") ==
        "pack.xyz:2: Properties holds both 'bin' and 'color': give one");
    // A line just under the limit is read whole (the chunked reader appends its pieces).
    const std::string comment(100000, 'x');
    std::istringstream in("1\nnote=" + comment + " " + kHeader + "1 0 0 0 0.05 0\n");
    BOOST_TEST(read_xyz(in, "pack.xyz").metadata.get("note")->size() == comment.size());
}

// Reliability finding 12: `bin` was cast to int unchecked (4294967297 became 1, -5 was
// kept); the dump reader refused anything outside [0, 10^6]. One rule for both readers.
BOOST_AUTO_TEST_CASE(bin_keeps_the_readers_one_range) {
    for (const std::string bin : {"4294967297", "-5", "1000001"}) {
        BOOST_TEST(read_error("1\n" + kHeader + "1 0 0 0 0.05 " + bin + "\n") ==
                   "pack.xyz:3: bin '" + bin + "' is not an integer in [0, 1000000]");
    }
    std::istringstream in("1\n" + kHeader + "1 0 0 0 0.05 1000000\n");
    BOOST_TEST(read_xyz(in, "pack.xyz").particles.at(0).color == 1000000);
}

// Reliability finding 14: a Latin-1 byte in a header value reached the JSON outputs, whose
// writer failed after a whole measure ("invalid UTF-8 byte"). Refused at input.
BOOST_AUTO_TEST_CASE(header_text_must_be_utf8) {
    BOOST_TEST(read_error("1\nnote=caf\xe9 " + kHeader + "1 0 0 0 0.05 0\n") ==
               "pack.xyz:2: header entry 'note=caf\\xe9' is not UTF-8 (a Latin-1 byte?): header "
               "text must be UTF-8");
    std::istringstream in("1\nnote=caf\xc3\xa9 " + kHeader + "1 0 0 0 0.05 0\n");
    BOOST_TEST(*read_xyz(in, "pack.xyz").metadata.get("note") == "caf\xc3\xa9");
    BOOST_TEST(sgmp::is_utf8("\xe2\x82\xac \xf0\x9f\x98\x80"));
    for (const std::string bad :
         {"\x80", "\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80", "\xe2\x82"}) {
        BOOST_TEST(!sgmp::is_utf8(bad));
    }
}

BOOST_AUTO_TEST_CASE(binary_bytes_are_escaped_in_messages) {
    BOOST_TEST(read_error("\x1b[2J\xff\n") ==
               "pack.xyz:1: expected the particle count, found '\\x1b[2J\\xff'");
}

BOOST_AUTO_TEST_CASE(a_claimed_count_allocates_nothing_before_its_lines_arrive) {
    // A 100-byte file claiming 10^15 or 2^63 - 1 particles once died in reserve().
    BOOST_TEST(read_error("1000000000000000\n" + kHeader + "1 0 0 0 0.1 0\n") ==
               "pack.xyz:3: file ends after 1 of 1000000000000000 particle lines");
    BOOST_TEST(read_error("9223372036854775807\n" + kHeader) ==
               "pack.xyz:2: file ends after 0 of 9223372036854775807 particle lines");
}

BOOST_AUTO_TEST_SUITE_END()

// An extended XYZ's own orthogonal cell is its box (walls at the Lattice's x and z faces,
// the floor at the Origin's y), taken as the container only when the spheres reach it, as
// a dump's box; a `container` key that differs from the cell is kept and named in one
// warning; a skewed cell gives no container.
BOOST_AUTO_TEST_CASE(the_lattice_cell_is_the_container_unless_a_key_says_otherwise) {
    const sgmp::testing::TestDirectory scratch("xyz_cell");
    const std::filesystem::path dir = scratch.path();
    const auto read = [&](const std::string& header) {
        std::ofstream(dir / "c.xyz")
            << "1\n"
            << header << " Properties=species:S:1:pos:R:3:radius:R:1\nAr 1 1 1 0.5\n";
        return read_pack_file(dir / "c.xyz", ReadOptions{});
    };
    const PackRead own = read(R"(Lattice="1 0 0 0 7 0 0 0 1" Origin="0.5 0.5 0.5")");
    BOOST_TEST(own.pack.metadata.get("container").value_or("") == "0.5 1.5 0.5 1.5 0.5");
    BOOST_TEST(own.pack.metadata.get("container_from").value_or("") == "box");
    BOOST_TEST(own.warnings.empty());
    const std::string far = sgmp::testing::input_error_of(
        [&] { read(R"(Lattice="6 0 0 0 7 0 0 0 8" Origin="0.5 0.5 0.5")"); });
    BOOST_TEST(
        far.find("7 d of clearance beyond contact from the box's z_max side") != std::string::npos,
        far);
    const PackRead keyed = read(R"(Lattice="6 0 0 0 7 0 0 0 8" container="0 1 0 1 0")");
    BOOST_TEST(keyed.pack.metadata.get("container").value_or("") == "0 1 0 1 0");
    BOOST_TEST_REQUIRE(keyed.warnings.size() == 1U);
    BOOST_TEST(keyed.warnings[0].find("'0 6 0 8 0'") != std::string::npos, keyed.warnings[0]);
    const PackRead skewed = read(R"(Lattice="6 0 0 1 7 0 0 0 8")");
    BOOST_TEST(!skewed.pack.metadata.contains("container"));
}

// Periodic sides travel with the file: an extended XYZ says pbc="T F T" (ASE and OVITO read
// periodic x and z), a dump "pp ff pp"; either read back as sides=periodic, and an ASE file
// with pbc="T F T" and no sides key is periodic too. Wall packs keep pbc="F F F".
BOOST_AUTO_TEST_CASE(periodic_sides_are_written_as_pbc_and_read_back) {
    const sgmp::testing::TestDirectory scratch("xyz_pbc");
    const std::filesystem::path dir = scratch.path();
    Pack pack;
    pack.metadata.set("sides", "periodic");
    pack.particles = {Particle{1, Vec3(0.6, -0.5, 0.0), 0.05, 0}};
    for (const char* name : {"p.xyz", "p.dump"}) {
        write_pack_as(dir / name, pack, *format_from_extension(dir / name), WriteOptions{true});
        const Pack back = read_pack_file(dir / name);
        BOOST_TEST(back.metadata.get("sides").value_or("") == "periodic", name);
        BOOST_TEST(container_of(back).periodic, name);
    }
    std::ifstream xyz(dir / "p.xyz");
    std::string line;
    std::getline(xyz, line);
    std::getline(xyz, line);
    BOOST_TEST(line.find("pbc=\"T F T\"") != std::string::npos, line);
    // On the cell's floor: periodic sides are not walls, so the box is reached.
    std::ofstream(dir / "ase.xyz") << "1\nLattice=\"2 0 0 0 2 0 0 0 2\" pbc=\"T F T\" "
                                      "Properties=species:S:1:pos:R:3:radius:R:1\nAr 1 0.5 1 0.5\n";
    BOOST_TEST(read_pack_file(dir / "ase.xyz").metadata.get("sides").value_or("") == "periodic");
    pack.metadata = {};
    write_pack_as(dir / "w.xyz", pack, PackFormat::xyz, WriteOptions{true});
    std::ifstream walls(dir / "w.xyz");
    std::getline(walls, line);
    std::getline(walls, line);
    BOOST_TEST(line.find("pbc=\"F F F\"") != std::string::npos, line);
}
