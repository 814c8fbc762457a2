// The scene text: deterministic, one sphere per kept particle (cut-aways against a brute
// count over the centres), views and cuts parsed as documented.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/render/palette.hpp"
#include "sgmp/render/scene.hpp"

using namespace sgmp;
using namespace sgmp::render;

namespace {

Pack small_pack(std::uint64_t seed) {
    engine::PackRequest request;
    request.count = 300;
    request.arrangement = engine::Arrangement::LooseRandom;
    request.seed = seed;
    return engine::make_pack(request);
}

SceneOptions with_cut(const std::string& cut, const std::string& view = "iso") {
    SceneOptions o;
    o.cut = *parse_cut(cut);
    o.view = *parse_view(view);
    return o;
}

}  // namespace

BOOST_AUTO_TEST_CASE(scene_is_deterministic_and_holds_every_sphere) {
    const Pack pack = small_pack(1);
    const SceneOptions o;
    const std::string a = povray_scene(pack, o);
    BOOST_TEST(a == povray_scene(pack, o));
    BOOST_TEST(scene_sphere_count(a) == pack.particles.size());
    BOOST_TEST(a.find("camera {") != std::string::npos);
    BOOST_TEST(a.find("cylinder {") != std::string::npos);  // the outline
    SceneOptions height = o;
    height.coloring = Coloring::Height;
    height.container = ContainerStyle::Walls;
    const std::string b = povray_scene(pack, height);
    BOOST_TEST(scene_sphere_count(b) == pack.particles.size());
    BOOST_TEST(b.find("box {") != std::string::npos);
    BOOST_TEST(b.find("cylinder {") == std::string::npos);
}

// Colour by species: every sphere of species k (1, 2, …) wears palette colour k − 1; a
// 2:1 blend gives as many spheres of each texture as the pack has of each species.
BOOST_AUTO_TEST_CASE(species_colouring_follows_the_species) {
    engine::PackRequest request;
    request.count = 300;
    request.arrangement = engine::Arrangement::LooseRandom;
    request.size_modes = {{1.0, 2.0 / 3.0}, {0.6, 1.0 / 3.0}};
    const Pack pack = engine::make_pack(request);
    SceneOptions o;
    o.coloring = Coloring::Species;
    const std::string scene = povray_scene(pack, o);
    std::size_t first = 0;
    std::size_t second = 0;
    for (const Particle& p : pack.particles) {
        (p.species == 1 ? first : second) += 1;
    }
    const auto count = [&](const std::string& needle) {
        std::size_t n = 0;
        for (std::size_t at = scene.find(needle); at != std::string::npos;
             at = scene.find(needle, at + 1)) {
            ++n;
        }
        return n;
    };
    BOOST_TEST(first == 200u);
    BOOST_TEST(count(" texture{Bin0}}") == first);
    BOOST_TEST(count(" texture{Bin1}}") == second);
    BOOST_TEST((parse_coloring("species") == std::optional<Coloring>(Coloring::Species)));
}

// Each cut keeps exactly the spheres a brute test of the rule in cut.hpp keeps, over
// several seeds and views.
BOOST_AUTO_TEST_CASE(cuts_drop_exactly_the_spheres_in_front_of_the_plane) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const Pack pack = small_pack(seed);
        const double d = mean_diameter(pack);
        for (const std::string view : {"iso", "front", "top", "120,-20"}) {
            const View v = *parse_view(view);
            const Vec3 h(std::sin(v.azimuth * M_PI / 180), 0.0, std::cos(v.azimuth * M_PI / 180));
            std::size_t half = 0;
            std::size_t slice = 0;
            std::size_t z_positive = 0;
            std::size_t y_below = 0;
            for (const Particle& p : pack.particles) {
                const double s = h.dot(p.center);  // the container's axis is x = z = 0
                half += s <= 0.0 ? 1 : 0;
                slice += std::abs(s) <= d ? 1 : 0;
                z_positive += p.center.z() > 0.0 ? 0 : 1;
                y_below += p.center.y() < -0.2 ? 0 : 1;
            }
            BOOST_TEST(scene_sphere_count(povray_scene(pack, with_cut("half", view))) == half);
            BOOST_TEST(scene_sphere_count(povray_scene(pack, with_cut("slice", view))) == slice);
            BOOST_TEST(scene_sphere_count(povray_scene(pack, with_cut("z>0", view))) == z_positive);
            BOOST_TEST(scene_sphere_count(povray_scene(pack, with_cut("y<-0.2", view))) == y_below);
            BOOST_TEST(half > 0U);
            BOOST_TEST(half < pack.particles.size());
            BOOST_TEST(slice > 0U);
            BOOST_TEST(slice < pack.particles.size());
        }
    }
}

BOOST_AUTO_TEST_CASE(views_and_cuts_parse_as_documented) {
    BOOST_TEST(parse_view("top")->elevation == 90.0);
    BOOST_TEST(parse_view("10,-30")->azimuth == 10.0);
    BOOST_TEST(!parse_view("10,91"));
    BOOST_TEST(!parse_view("10"));
    BOOST_TEST(!parse_view("a,b"));
    BOOST_TEST(!parse_cut("w>0"));
    BOOST_TEST(!parse_cut("z=0"));
    BOOST_TEST(!parse_cut("z>"));
    BOOST_TEST(!parse_cut("z>nan"));
    BOOST_TEST(parse_cut("x<0.25")->value == 0.25);
    // u = (cos θ sin φ, sin θ, cos θ cos φ) is a unit vector; φ = 90°, θ = 0 looks from +X.
    const Vec3 u = toward_camera(View{90.0, 0.0});
    BOOST_TEST(std::abs(u.x() - 1.0) < 1e-15);
    BOOST_TEST(std::abs(toward_camera(View{33.0, 41.0}).norm() - 1.0) < 1e-15);
}

BOOST_AUTO_TEST_CASE(palettes) {
    // Tableau 10's first colour, #1f77b4; bins wrap around modulo 10.
    BOOST_TEST(std::abs(bin_color(0).r - 0x1f / 255.0) < 1e-15);
    BOOST_TEST(bin_color(13).g == bin_color(3).g);
    BOOST_TEST(bin_color(-1).b == bin_color(9).b);
    // viridis ends: #440154 and #fde725; clamped outside [0, 1].
    BOOST_TEST(std::abs(height_color(0.0).b - 0x54 / 255.0) < 1e-15);
    BOOST_TEST(std::abs(height_color(1.0).g - 0xe7 / 255.0) < 1e-15);
    BOOST_TEST(height_color(2.0).r == height_color(1.0).r);
    // sRGB 0.5 is linear 0.21404 (the standard transfer function).
    BOOST_TEST(std::abs(linear_from_srgb(Rgb{0.5, 0.5, 0.5}).r - 0.2140411404) < 1e-9);
}
