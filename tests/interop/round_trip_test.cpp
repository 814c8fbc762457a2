// Every writer read back by the pack library's readers, over many engine packs: bit-identical
// centres and radii (shortest round-trip text), the bins, no overlap, and the same bytes
// every time.
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/engine/pack_checks.hpp"
#include "sgmp/pack/dump_format.hpp"
#include "sgmp/pack/lammps_data_format.hpp"
#include "sgmp/pack/pack_extent.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/size_modes.hpp"
#include "sgmp/pack/vtk_format.hpp"
#include "sgmp/pack/xyz_format.hpp"
#include "test_support.hpp"

using namespace sgmp;
namespace fs = std::filesystem;

namespace {

Pack engine_pack(std::uint64_t seed) {
    engine::PackRequest request;
    request.count = 150 + 10 * seed;
    request.arrangement =
        seed % 2 ? engine::Arrangement::LooseRandom : engine::Arrangement::LargeDense;
    request.seed = seed;
    if (seed % 3 == 0) {
        request.size_modes = *sgmp::parse_size_modes("1:0.7,0.5:0.3");
    }
    return engine::make_pack(request);
}

template <class Write>
std::string text_of(Write write, const Pack& pack) {
    std::ostringstream out;
    write(out, pack);
    return out.str();
}

void check_same_particles(const Pack& a, const Pack& b) {
    BOOST_TEST_REQUIRE(a.particles.size() == b.particles.size());
    for (std::size_t i = 0; i < a.particles.size(); ++i) {
        BOOST_TEST(a.particles[i].id == b.particles[i].id);
        BOOST_TEST((a.particles[i].center.array() == b.particles[i].center.array()).all());
        BOOST_TEST(a.particles[i].radius == b.particles[i].radius);
        BOOST_TEST(a.particles[i].color == b.particles[i].color);
        BOOST_TEST(a.particles[i].species == b.particles[i].species);
    }
}

/// Overlaps deeper than 1e-9 d, the floor of the metrics and of `sgmp pack`'s own check
/// (spheres placed touching in floating point may overlap by ~1e-16 d).
std::size_t overlaps_of(const Pack& pack) {
    const double floor = 1e-9 * *pack.metadata.get_number("diameter");
    return engine::check_pack(pack.particles, container_of(pack), floor, 1e300).overlaps;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(round_trip)

BOOST_AUTO_TEST_CASE(every_format_reads_back_bit_identical_with_no_overlap) {
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        const Pack pack = engine_pack(seed);
        BOOST_TEST_REQUIRE(overlaps_of(pack) == 0u);
        const std::string xyz = text_of(write_xyz, pack);
        const std::string data = text_of(write_lammps_data, pack);
        const std::string dump = text_of(write_dump_custom, pack);
        std::istringstream xyz_in(xyz);
        std::istringstream data_in(data);
        std::istringstream dump_in(dump);
        const Pack from_xyz = read_xyz(xyz_in, "xyz");
        const Pack from_data = read_lammps_data(data_in, "data");
        const Pack from_dump = read_dump_custom(dump_in, "dump");
        check_same_particles(pack, from_xyz);
        check_same_particles(pack, from_data);
        check_same_particles(pack, from_dump);
        BOOST_TEST(overlaps_of(from_data) == 0u);
        // xyz → data → xyz: the provenance survives with the particles.
        BOOST_TEST((from_data.metadata.get("seed") == pack.metadata.get("seed")));
        BOOST_TEST((from_data.metadata.get("container") == pack.metadata.get("container")));
        // The same pack gives the same bytes.
        BOOST_TEST(text_of(write_lammps_data, from_data) == text_of(write_lammps_data, [&] {
                       Pack again = pack;
                       again.metadata.set("source_format", "lammps data");
                       return again;
                   }()));
        if (seed % 3 != 0) {
            // A dump keeps no header, so its types (size modes) are not rebuilt from it.
            BOOST_TEST(text_of(write_dump_custom, from_dump) == dump);
        }
        BOOST_TEST(text_of(write_vtk_particles, pack) == text_of(write_vtk_particles, pack));
    }
}

BOOST_AUTO_TEST_CASE(atom_types_follow_the_size_modes) {
    const Pack pack = engine_pack(3);  // modes 1 and 0.5
    std::istringstream in(text_of(write_dump_custom, pack));
    std::string line;
    std::size_t small = 0;
    std::size_t checked = 0;
    while (std::getline(in, line) && line != "ITEM: ATOMS id type x y z radius bin species") {
    }
    const double scale = *pack.metadata.get_number("diameter");
    for (const auto& p : pack.particles) {
        std::getline(in, line);
        std::istringstream fields(line);
        long long id = 0;
        int type = 0;
        fields >> id >> type;
        BOOST_TEST(type == (2.0 * p.radius < 0.75 * scale ? 2 : 1));
        BOOST_TEST(type == p.species);  // modes in order: the species are the types here
        small += type == 2 ? 1 : 0;
        ++checked;
    }
    BOOST_TEST(checked == pack.particles.size());
    BOOST_TEST(small > 0u);
}

BOOST_AUTO_TEST_CASE(the_file_layer_writes_all_or_nothing_and_only_with_force) {
    const sgmp::testing::TestDirectory scratch("interop_round_trip");
    const Pack pack = engine_pack(1);
    for (const PackFormat format : all_pack_formats()) {
        const fs::path out = scratch.path() / ("p" + std::string(extension_of(format)));
        write_pack_as(out, pack, format, WriteOptions{});
        const std::string first = sgmp::testing::read_bytes(out);
        BOOST_CHECK_THROW(write_pack_as(out, pack, format, WriteOptions{}), std::runtime_error);
        write_pack_as(out, pack, format, WriteOptions{true});
        BOOST_TEST(sgmp::testing::read_bytes(out) ==
                   first);                  // deterministic bytes, compressed ones too
        if (!has_container_file(format)) {  // VTK is written only
            const Pack back = read_pack_file(out);
            check_same_particles(pack, back);
        }
    }
    BOOST_TEST(fs::exists(scratch.path() / "p.container.vtk"));
    BOOST_TEST(fs::exists(scratch.path() / "p.container.vtp"));
    BOOST_TEST(container_file_for("a/b.vtk") == fs::path("a/b.container.vtk"));
    BOOST_TEST(container_file_for("a/b.vtp") == fs::path("a/b.container.vtp"));
    // A name that does not match the format, and a pack the format cannot carry: an
    // error naming the format and the field, and no file.
    BOOST_CHECK_THROW(write_pack_as(scratch.path() / "q.xyz", pack, PackFormat::xyz_gz, {}),
                      std::invalid_argument);
    Pack zero = pack;
    zero.particles[0].id = 0;
    try {
        write_pack_as(scratch.path() / "z.data", zero, PackFormat::lammps_data, {});
        BOOST_FAIL("id 0 was written to a data file");
    } catch (const std::invalid_argument& e) {
        BOOST_TEST(std::string(e.what()) ==
                   "format data cannot carry id 0: LAMMPS atom ids must be positive");
    }
    BOOST_TEST(!fs::exists(scratch.path() / "z.data"));
    BOOST_TEST(!fs::exists(scratch.path() / "q.xyz"));
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(scratch.path())) {
        ++files;
    }
    BOOST_TEST(files == 8u);  // the six formats plus two containers, no temporaries
}

BOOST_AUTO_TEST_SUITE_END()
