// The scene text: deterministic, one sphere per kept particle (cut-aways against a brute
// count over the centres), views and cuts parsed as documented.
#include <Eigen/Geometry>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/render/legend.hpp"
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

// Colour by the caller's values: the largest value wears viridis' end colour, the least
// its start, NaN grey; the key holds the caption, the tick labels of the range and the
// length scale; without the key there is no text and the camera looks at the box's centre.
BOOST_AUTO_TEST_CASE(value_colouring_and_its_key) {
    const Pack pack = small_pack(2);
    SceneOptions o;
    o.coloring = Coloring::Values;
    o.caption = {"Z", "gap <= 1e-3 d"};
    o.values.assign(pack.particles.size(), 3.0);
    o.values[0] = 0.0;
    o.values[1] = 6.0;
    o.values[2] = std::nan("");
    const std::string scene = povray_scene(pack, o);
    const auto colour_of = [](const Rgb& srgb) {
        const Rgb c = linear_from_srgb(srgb);
        char text[120];
        std::snprintf(text, sizeof text, "rgb <%.6f,%.6f,%.6f>", c.r, c.g, c.b);
        return std::string(text);
    };
    const auto sphere_line = [&](std::size_t i) {
        std::size_t at = 0;
        for (std::size_t k = 0; k <= i; ++k) {
            at = scene.find("sphere{", at + (k ? 1 : 0));
        }
        return scene.substr(at, scene.find('\n', at) - at);
    };
    BOOST_TEST(sphere_line(0).find(colour_of(height_color(0.0))) != std::string::npos);
    BOOST_TEST(sphere_line(1).find(colour_of(height_color(1.0))) != std::string::npos);
    BOOST_TEST(sphere_line(2).find(colour_of(Rgb{0.75, 0.75, 0.75})) != std::string::npos);
    for (const char* label : {"\"Z\"", "\"gap <= 1e-3 d\"", "\"0\"", "\"3\"", "\"6\"", " d\""}) {
        BOOST_TEST(scene.find(label) != std::string::npos, label);
    }
    // A fixed range shared by several pictures: 6 on 0..12 is viridis' middle, not its end.
    o.value_limits = std::pair{0.0, 12.0};
    const std::string fixed = povray_scene(pack, o);
    BOOST_TEST(fixed.find(colour_of(height_color(0.5))) != std::string::npos);
    BOOST_TEST(fixed.find("\"12\"") != std::string::npos);
    for (const auto& bad : {std::pair{1.0, 1.0}, std::pair{0.0, std::nan("")}}) {
        o.value_limits = bad;
        BOOST_CHECK_THROW(povray_scene(pack, o), std::invalid_argument);
    }
    o.value_limits.reset();
    o.values.pop_back();
    BOOST_CHECK_THROW(povray_scene(pack, o), std::invalid_argument);
    SceneOptions plain;
    plain.legend = false;
    BOOST_TEST(povray_scene(pack, plain).find("text {") == std::string::npos);
}

// The key's geometry (legend.hpp): every corner of its marks projects into the key's strip
// of the image, u ∈ [1 − 2f, 1], |v| ≤ 1; the length scale's bar, projected back onto the
// target plane, is n mean diameters long, n one of 1, 2, 5, 10, …, and at most 80 % of the
// strip wide.
BOOST_AUTO_TEST_CASE(the_key_lies_in_its_strip_and_its_scale_is_true) {
    OverlayFrame f;
    f.location = Vec3(3.0, 2.0, 5.0);
    f.forward = Vec3(-3.0, -1.0, -5.0).normalized();
    f.right = f.forward.cross(Vec3::UnitY()).normalized();
    f.up = f.right.cross(f.forward);
    f.tan_v = std::tan(15.0 * M_PI / 180.0);
    f.tan_h = 1.5 * f.tan_v;
    f.distance = 6.0;
    LegendContent c;
    c.caption = {"height"};
    c.bar = true;
    c.lo = 0.0;
    c.hi = 20.0;
    c.diameter = 0.1;
    const std::string scene = legend_scene(f, c);
    const auto screen = [&](const Vec3& p) {
        const Vec3 q = p - f.location;
        const double depth = q.dot(f.forward);
        return std::pair{q.dot(f.right) / depth / f.tan_h, q.dot(f.up) / depth / f.tan_v};
    };
    std::vector<Vec3> corners;
    for (std::size_t at = scene.find("triangle {"); at != std::string::npos;
         at = scene.find("triangle {", at + 1)) {
        double v[9];
        BOOST_TEST_REQUIRE(
            std::sscanf(scene.c_str() + at, "triangle { <%lf,%lf,%lf>,<%lf,%lf,%lf>,<%lf,%lf,%lf>",
                        &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6], &v[7], &v[8]) == 9);
        for (int k = 0; k < 3; ++k) {
            corners.emplace_back(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
        }
    }
    BOOST_TEST(corners.size() >= 6U * 48U);  // the bar's segments, two triangles each
    for (const Vec3& p : corners) {
        const auto [u, v] = screen(p);
        BOOST_TEST((u >= 1.0 - 2.0 * kLegendStrip - 1e-5 && u <= 1.0 + 1e-5), "u = " << u);
        BOOST_TEST(std::abs(v) <= 1.0 + 1e-5, "v = " << v);
    }
    // The scale bar is the last mesh: its lower corners, scaled from the overlay plane
    // (depth D/4) to the target plane (depth D).
    const Vec3 a = corners[corners.size() - 6], b = corners[corners.size() - 5];
    const double length = (b - a).norm() * 4.0;
    const double n = length / c.diameter;
    const double rounded = std::round(n);
    BOOST_TEST(std::abs(n - rounded) <= 1e-4 * rounded);
    const double mantissa = rounded / std::pow(10.0, std::floor(std::log10(rounded)));
    BOOST_TEST((mantissa == 1.0 || mantissa == 2.0 || mantissa == 5.0));
    BOOST_TEST(screen(b).first - screen(a).first <= 0.8 * 2.0 * kLegendStrip + 1e-6);
    BOOST_TEST(scene.find("\"" + std::to_string(static_cast<int>(rounded)) + " d\"") !=
               std::string::npos);
}
