// Pictures in the cross-validation report: which packs are pictured (N = 9000 or the
// largest count with both roles, the lowest seed per group, no variants), and the real
// `sgmp-compare crossval --pictures` with and without POV-Ray.

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/render/png_info.hpp"
#include "sgmp/report/report_pictures.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace sgmp::report;

namespace {

ManifestEntry entry(Role role, const std::string& group, std::size_t count, std::uint64_t seed) {
    return ManifestEntry{
        role, group,        count,
        seed, std::nullopt, group + "-" + std::to_string(count) + "-" + std::to_string(seed)};
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_pictured_packs) {
    std::vector<ManifestEntry> m = {entry(Role::Candidate, "loose-random", 9000, 2),
                                    entry(Role::Candidate, "loose-random", 9000, 1),
                                    entry(Role::Candidate, "single-column", 9000, 3),
                                    entry(Role::Candidate, "loose-random", 300, 1),
                                    entry(Role::Reference, "DEM mu=0.5", 9000, 4),
                                    entry(Role::Reference, "DEM mu=0.5", 9000, 2),
                                    entry(Role::Variant, "DEM mu=0.5", 9000, 1),
                                    entry(Role::Reference, "DEM mu=0.01", 300, 1)};
    const auto c = choose_pictures(m);
    BOOST_TEST_REQUIRE(c.size() == 3U);
    BOOST_TEST(c[0].group == "loose-random");
    BOOST_TEST(c[0].seed == 1U);  // the lowest seed, not the first listed
    BOOST_TEST(c[1].group == "single-column");
    BOOST_TEST(c[2].group == "DEM mu=0.5");
    BOOST_TEST(c[2].reference);
    BOOST_TEST(c[2].seed == 2U);  // the variant's seed 1 is not a reference pour
    BOOST_TEST(c[2].file == "pictures/n9000-r3-dem-mu-0.5.png");
    // Without references at 9000 the largest count with both roles is pictured.
    m.erase(m.begin() + 4, m.begin() + 7);
    const auto fallback = choose_pictures(m);
    BOOST_TEST_REQUIRE(fallback.size() == 2U);
    BOOST_TEST(fallback[0].count == 300U);
    BOOST_TEST(fallback[1].group == "DEM mu=0.01");
    BOOST_TEST(choose_pictures({entry(Role::Candidate, "a", 9000, 1)}).empty());
}

BOOST_AUTO_TEST_CASE(crossval_pictures_with_and_without_povray) {
    const sgmp::testing::TestDirectory scratch("render-crossval-pictures");
    const fs::path& dir = scratch.path();
    std::string manifest = "role,group,count,seed,seconds,path\n";
    for (const auto& [arrangement, role] :
         {std::pair{sgmp::engine::Arrangement::LooseRandom, "candidate"},
          std::pair{sgmp::engine::Arrangement::SmallDense, "reference"}}) {
        for (std::uint64_t seed = 1; seed <= 2; ++seed) {
            sgmp::engine::PackRequest request;
            request.count = 300;
            request.arrangement = arrangement;
            request.seed = seed;
            const std::string name = std::string(role) + std::to_string(seed) + ".xyz";
            sgmp::write_pack_file(dir / name, sgmp::engine::make_pack(request), true);
            manifest += std::string(role) + "," +
                        (role == std::string("candidate") ? "loose-random" : "DEM mu=0.5") +
                        ",300," + std::to_string(seed) + ",1.0," + name + "\n";
        }
    }
    std::ofstream(dir / "manifest.csv") << manifest;
    auto crossval = [&](const std::string& args, const std::string& env) {
        return sgmp::testing::run_command(
                   "cd '" + dir.string() + "' && " + env + " '" + SGMP_COMPARE +
                       "' crossval --manifest manifest.csv --no-voronoi " + args,
                   dir)
            .status;
    };
    BOOST_TEST_REQUIRE(crossval("--pictures --picture-size 64 --out cv", "") == 0);
    const std::string md = sgmp::testing::read_bytes(dir / "cv" / "report.md");
    BOOST_TEST(md.find("\n\n## Pictures\n") != std::string::npos);
    BOOST_TEST(sgmp::testing::read_bytes(dir / "cv" / "index.html").find(">Pictures</h2>") !=
               std::string::npos);
    for (const char* file :
         {"pictures/n300-c1-loose-random.png", "pictures/n300-r2-dem-mu-0.5.png"}) {
        const std::string png = sgmp::testing::read_bytes(dir / "cv" / file);
        const auto size = sgmp::render::png_size(png);
        BOOST_TEST_REQUIRE(size.has_value(), file);
        BOOST_TEST(size->width == 64U);
        BOOST_TEST(size->height == 64U);
        BOOST_TEST(md.find(std::string("(") + file + ")") != std::string::npos, file);
    }
    const std::string html = sgmp::testing::read_bytes(dir / "cv" / "index.html");
    BOOST_TEST(html.find("<img src=\"pictures/n300-c1-loose-random.png\"") != std::string::npos);

    // Without POV-Ray the report is still written and says so in one line.
    BOOST_TEST_REQUIRE(crossval("--pictures --out cv-none", "SGMP_POVRAY=") == 0);
    const std::string none = sgmp::testing::read_bytes(dir / "cv-none" / "report.md");
    const auto at = none.find("No pictures: POV-Ray was not found");
    BOOST_TEST(at != std::string::npos);
    BOOST_TEST(none.find('\n', at) == none.find(".\n", at) + 1);  // one line
    BOOST_TEST(!fs::exists(dir / "cv-none" / "pictures"));
    BOOST_TEST(fs::exists(dir / "cv-none" / "index.html"));
    // Pictures are off unless asked for.
    BOOST_TEST_REQUIRE(crossval("--out cv-off", "") == 0);
    BOOST_TEST(sgmp::testing::read_bytes(dir / "cv-off" / "report.md").find("## Pictures") ==
               std::string::npos);
}
