// The format registry, the extended XYZ conventions (bin, Lattice, Origin) and the
// readers' tolerance of files from elsewhere (frames, bare keys, names in any case,
// species-only files).
#include <boost/test/unit_test.hpp>
#include <sstream>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/pack_format.hpp"
#include "sgmp/pack/xyz_format.hpp"

using namespace sgmp;

namespace {

PackRead read_text(const std::string& text, const ReadOptions& options = {}) {
    std::istringstream in(text);
    return read_xyz(in, "f.xyz", options);
}

std::string error_of(const std::string& text, const ReadOptions& options = {}) {
    try {
        read_text(text, options);
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

std::string frame(int n, double x) {
    std::ostringstream out;
    out << n << "\nProperties=pos:R:3:radius:R:1 step=" << x << "\n";
    for (int i = 0; i < n; ++i) {
        out << x << " 0 " << i << " 0.25\n";
    }
    return out.str();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(formats)

BOOST_AUTO_TEST_CASE(one_name_table_gives_names_endings_and_the_rule) {
    for (const PackFormat format : all_pack_formats()) {
        BOOST_TEST((parse_pack_format(to_string(format)) == format));
        BOOST_TEST(
            (format_from_extension("dir.d/pack" + std::string(extension_of(format))) == format));
    }
    BOOST_TEST(all_pack_formats().size() == 6u);
    BOOST_TEST(pack_format_choices() == "one of xyz, xyz.gz, data, dump, vtk, vtp");
    BOOST_TEST(!parse_pack_format("vtu").has_value());
    BOOST_TEST(has_container_file(PackFormat::vtp));
    BOOST_TEST(!has_container_file(PackFormat::lammps_data));
    BOOST_TEST(!format_from_extension("pack.txt").has_value());
    BOOST_TEST(!format_from_extension(".xyz").has_value());  // a name that is only an ending
    BOOST_TEST((format_from_extension("a.xyz.gz") == PackFormat::xyz_gz));
}

BOOST_AUTO_TEST_CASE(xyz_header_carries_bin_lattice_and_origin) {
    Pack pack;
    pack.metadata.set("container", "-0.625 0.625 -0.625 0.625 -0.625");
    pack.particles.push_back(Particle{1, Vec3(0, -0.5, 0), 0.125, 3});
    pack.particles.push_back(Particle{2, Vec3(0.25, 0.5, 0), 0.25, 7});
    std::ostringstream out;
    write_xyz(out, pack);
    // H = top of the highest sphere − floor = (0.5 + 0.25) + 0.625 = 1.375, exact in binary.
    BOOST_TEST(out.str() ==
               "2\nProperties=id:I:1:pos:R:3:radius:R:1:bin:I:1 Lattice=\"1.25 0 0 0 1.375 0 0 "
               "0 1.25\" Origin=\"-0.625 -0.625 -0.625\" pbc=\"F F F\" "
               "container=\"-0.625 0.625 -0.625 0.625 -0.625\"\n"
               "1 0 -0.5 0 0.125 3\n2 0.25 0.5 0 0.25 7\n");
    // Lattice and Origin are derived: read back, they are not metadata.
    const PackRead back = read_text(out.str());
    BOOST_TEST(back.pack.metadata.entries().size() == 1u);
    BOOST_TEST(back.pack.particles[1].color == 7);
}

BOOST_AUTO_TEST_CASE(old_color_columns_names_in_any_case_and_bare_keys) {
    const PackRead read = read_text(
        "1\nproperties=ID:I:1:POS:R:3:Radius:R:1:Color:I:1 pbc=\"F F F\" relaxed done=T\n"
        "5 1 2 3 0.5 4\n");
    BOOST_TEST(read.pack.particles[0].id == 5);
    BOOST_TEST(read.pack.particles[0].radius == 0.5);
    BOOST_TEST(read.pack.particles[0].color == 4);
    BOOST_TEST(*read.pack.metadata.get("relaxed") == "T");
    BOOST_TEST(*read.pack.metadata.get("done") == "T");
}

BOOST_AUTO_TEST_CASE(species_only_files_need_a_radius) {
    const std::string text = "2\nProperties=species:S:1:pos:R:3\nAr 0 0 0\nAr 1 0 0\n";
    BOOST_TEST(error_of(text) ==
               "f.xyz:2: Properties lacks a 'radius' or 'diameter' column; give the radius "
               "(--radius R)");
    const PackRead read = read_text(text, ReadOptions{std::nullopt, 0.3});
    BOOST_TEST(read.pack.particles.size() == 2u);
    BOOST_TEST(read.pack.particles[1].radius == 0.3);
    BOOST_TEST(read.pack.particles[1].id == 2);  // ids by line when the file has none
}

BOOST_AUTO_TEST_CASE(frames_count_from_one_and_the_last_is_the_default) {
    const std::string text = frame(2, 1) + frame(3, 2) + "\n" + frame(1, 3) + "\n\n";
    const PackRead last = read_text(text);
    BOOST_TEST(last.frames == 3u);
    BOOST_TEST(last.frame == 3u);
    BOOST_TEST(last.pack.particles.size() == 1u);
    BOOST_TEST(*last.pack.metadata.get("step") == "3");
    const PackRead second = read_text(text, ReadOptions{2, std::nullopt});
    BOOST_TEST(second.pack.particles.size() == 3u);
    BOOST_TEST(second.pack.particles[2].center.x() == 2.0);
    BOOST_TEST(error_of(text, ReadOptions{4, std::nullopt}) ==
               "f.xyz: frame 4 does not exist: the file has 3 frame(s), counted from 1");
    BOOST_TEST(error_of(text, ReadOptions{0, std::nullopt}) ==
               "f.xyz: frame 0 does not exist: frames count from 1");
    // A bad later frame rejects the file even when an earlier one is asked for.
    BOOST_TEST(error_of(frame(1, 1) + "2\nProperties=pos:R:3:radius:R:1\n0 0 0 0.1\n",
                        ReadOptions{1, std::nullopt}) ==
               "f.xyz:6: file ends after 1 of 2 particle lines");
}

BOOST_AUTO_TEST_CASE(decimals_are_the_place_of_the_last_written_digit) {
    BOOST_TEST(*read_text("1\nProperties=pos:R:3:radius:R:1\n0.12345678 1 -2.5 0.1\n").decimals ==
               8);
    BOOST_TEST(*read_text("1\nProperties=pos:R:3:radius:R:1\n1.5e-05 1 2 3\n").decimals == 6);
    BOOST_TEST(*read_text("1\nProperties=pos:R:3:radius:R:1\n1 2 3E2 4\n").decimals == 0);
}

BOOST_AUTO_TEST_SUITE_END()
