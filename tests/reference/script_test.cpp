// The LIGGGHTS input script: template filling, parameters, seeds, processor grid.
#include <boost/test/unit_test.hpp>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/reference/input_script.hpp"
#include "sgmp/reference/pour_params.hpp"

using namespace sgmp::reference;

namespace {

bool is_prime(std::uint64_t n) {
    if (n < 2) {
        return false;
    }
    for (std::uint64_t f = 2; f * f <= n; ++f) {
        if (n % f == 0) {
            return false;
        }
    }
    return true;
}

/// The value of `variable <name> string <value>` in the script.
std::string script_variable(const std::string& script, const std::string& name) {
    const std::string key = "\nvariable " + name + " ";
    const auto at = script.find(key);
    BOOST_TEST_REQUIRE(at != std::string::npos, "no variable " << name);
    const auto line_end = script.find('\n', at + 1);
    const std::string line = script.substr(at + 1, line_end - at - 1);
    const auto string_at = line.find(" string ");
    BOOST_TEST_REQUIRE(string_at != std::string::npos);
    std::string rest = line.substr(string_at + 8);
    rest.erase(0, rest.find_first_not_of(' '));
    return rest.substr(0, rest.find(' '));
}

double number(const std::string& text) {
    double value = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(input_script)

BOOST_AUTO_TEST_CASE(placeholders_are_filled_and_unknown_ones_refused) {
    BOOST_TEST(fill_template("a {{x}} b {{y}}{{x}}", {{"x", "1"}, {"y", "2"}}) == "a 1 b 21");
    BOOST_TEST(fill_template("[{{x:4}}]", {{"x", "1"}}) == "[1   ]");
    BOOST_TEST(fill_template("[{{x:1}}]", {{"x", "123"}}) == "[123]");
    BOOST_CHECK_THROW(fill_template("a {{z}}", {{"x", "1"}}), std::invalid_argument);
    BOOST_CHECK_THROW(fill_template("a {{x", {{"x", "1"}}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(the_script_carries_every_parameter_exactly) {
    PourParams p;
    p.count = 1002;
    p.seed = 7;
    p.friction = 0.01;
    p.ranks = 2;
    const std::string script = pour_script(p, p.cloud_top());
    BOOST_TEST(script.find("{{") == std::string::npos);
    BOOST_TEST(script_variable(script, "count") == "1002");
    BOOST_TEST(script_variable(script, "friction") == "0.01");
    BOOST_TEST(script_variable(script, "youngs_modulus") == "1e+09");
    // The radius is written in the shortest form that reads back to exactly d/2, so the
    // dump (written with %.17g) gives back the sizing rule's radius bit for bit.
    BOOST_TEST(number(script_variable(script, "radius")) == p.diameter() / 2.0);
    BOOST_TEST(number(script_variable(script, "diameter")) == sgmp::diameter_for_count(1002));
    BOOST_TEST(script.find("processors      2 1 1") != std::string::npos);
    BOOST_TEST(script.find("pair_style  gran model hertz tangential history") != std::string::npos);
    BOOST_TEST(script.find("insert/pack") != std::string::npos);
    BOOST_TEST(script.find("read_data") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(tangential_damping_is_switched_on_the_pair_style_and_every_wall) {
    PourParams p;
    p.count = 150;
    p.tangential_damping = false;
    const std::string script = pour_script(p, p.cloud_top());
    BOOST_TEST(script_variable(script, "tangential_damping") == "off");
    std::size_t uses = 0;
    for (auto at = script.find("tangential_damping ${tangential_damping}"); at != std::string::npos;
         at = script.find("tangential_damping ${tangential_damping}", at + 1)) {
        ++uses;
    }
    BOOST_TEST(uses == 6u);  // the pair style, the floor and four walls
}

BOOST_AUTO_TEST_CASE(an_arrangement_start_reads_a_data_file) {
    PourParams p;
    p.count = 150;
    p.arrangement = "small-dense";
    const std::string script = pour_script(p, 0.5);
    BOOST_TEST(script.find("read_data       start.data") != std::string::npos);
    BOOST_TEST(script.find("insert/pack") == std::string::npos);
    BOOST_TEST(script_variable(script, "start_top") == "0.5");
}

BOOST_AUTO_TEST_CASE(liggghts_seeds_are_primes_above_10000_fixed_by_the_seed) {
    for (std::uint64_t seed : {0ULL, 1ULL, 2ULL, 12345678901ULL}) {
        const LiggghtsSeeds s = liggghts_seeds(seed);
        for (std::uint64_t prime : {s.particle_template, s.distribution, s.insertion}) {
            BOOST_TEST(prime > 10000u);
            BOOST_TEST(is_prime(prime));
        }
        BOOST_TEST(liggghts_seeds(seed).insertion == s.insertion);
    }
    BOOST_TEST(liggghts_seeds(1).insertion != liggghts_seeds(2).insertion);
    BOOST_TEST(next_prime(10000) == 10007u);
    BOOST_TEST(next_prime(10007) == 10007u);
}

BOOST_AUTO_TEST_CASE(the_cloud_holds_the_spheres_at_the_asked_fraction) {
    // N (π/6) d³ = f (L − d)² (h − d), h measured from the floor.
    for (std::size_t n : {150u, 9000u}) {
        PourParams p;
        p.count = n;
        const double d = p.diameter();
        const double h = p.cloud_top() + 0.625;
        const double solid = static_cast<double>(n) * std::numbers::pi / 6.0 * d * d * d;
        BOOST_TEST(solid / ((1.25 - d) * (1.25 - d) * (h - d)) == p.cloud_fraction,
                   boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(parameters_outside_their_range_are_refused_by_name) {
    PourParams p;
    p.count = 150;
    p.validate();
    p.youngs_modulus = 5e6;  // LIGGGHTS refuses 5e6 Pa and softer
    try {
        p.validate();
        BOOST_FAIL("a Young's modulus of 5e6 Pa was accepted");
    } catch (const std::invalid_argument& e) {
        BOOST_TEST(std::string(e.what()) == "youngs_modulus = 5e+06: must be above 5e6 Pa");
    }
    p.youngs_modulus = 1e9;
    p.restitution = 1.0;
    BOOST_CHECK_THROW(p.validate(), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(the_processor_grid_splits_horizontally) {
    const auto grid = [](int ranks, const std::string& processors = "") {
        PourParams p;
        p.ranks = ranks;
        p.processors = processors;
        return processor_grid(p);
    };
    BOOST_TEST(grid(1) == "1 1 1");
    BOOST_TEST(grid(2) == "2 1 1");
    BOOST_TEST(grid(4) == "2 1 2");  // the square container: a square grid
    BOOST_TEST(grid(4, "4,1,1") == "4 1 1");
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(blends_and_periodic_sides)

/// A bimodal blend of equal volumes (diameter ratio 1 : 0.5): 1 : 8 in number.
PourParams bimodal(std::size_t count) {
    PourParams p;
    p.count = count;
    p.size_modes = {{1.0, 0.5}, {0.5, 0.5}};
    p.fraction_basis = sgmp::FractionBasis::Volume;
    return p;
}

BOOST_AUTO_TEST_CASE(a_blend_holds_the_counts_and_diameters_of_the_pack_rule) {
    const PourParams p = bimodal(1002);
    const auto species = p.species();
    BOOST_TEST_REQUIRE(species.size() == 2u);
    // Number fractions 1/9 and 8/9: 111.33 and 890.67 round to 111 and 891.
    BOOST_TEST(species[0].count == 111u);
    BOOST_TEST(species[1].count == 891u);
    BOOST_TEST(species[1].diameter == 0.5 * species[0].diameter);
    // The generalised sizing rule (N/3)(pi/6) sum n_i (a_i s)^3 = phi*, in closed form.
    const double s =
        std::cbrt(18.0 * 0.63 / (std::numbers::pi * 1002.0 * (1.0 / 9.0 + 8.0 / 9.0 / 8.0)));
    BOOST_TEST(species[0].diameter == s, boost::test_tools::tolerance(1e-14));
    BOOST_TEST(p.diameter() == (111.0 * s + 891.0 * 0.5 * s) / 1002.0,
               boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(a_blend_is_inserted_by_one_number_based_distribution_of_its_counts) {
    PourParams p = bimodal(1002);
    const std::string script = pour_script(p, p.cloud_top());
    BOOST_TEST(script.find("particledistribution/discrete/numberbased") != std::string::npos);
    // Weights are the deterministic counts over N: 111/1002 and 891/1002.
    BOOST_TEST(script.find(" 2 template_1 " + sgmp::format_number(111.0 / 1002.0) + " template_2 " +
                           sgmp::format_number(891.0 / 1002.0)) != std::string::npos);
    BOOST_TEST(script.find("particles_in_region ${count} region cloud") != std::string::npos);
    BOOST_TEST(script.find("fix insert_cloud all insert/pack") != std::string::npos);
    // The time step follows the small spheres: radius = the smallest d/2.
    BOOST_TEST(number(script_variable(script, "radius")) == p.species()[1].diameter / 2.0,
               boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(periodic_sides_have_no_side_walls) {
    PourParams p = bimodal(1002);
    p.sides = sgmp::Sides::Periodic;
    const std::string periodic = pour_script(p, p.cloud_top());
    BOOST_TEST(periodic.find("\nboundary        p f p") != std::string::npos);
    BOOST_TEST(periodic.find("xplane") == std::string::npos);
    BOOST_TEST(periodic.find("zplane") == std::string::npos);
    BOOST_TEST(periodic.find("yplane -0.625") != std::string::npos);  // the floor is kept
    p.sides = sgmp::Sides::Walls;
    const std::string walls = pour_script(p, p.cloud_top());
    BOOST_TEST(walls.find("\nboundary        f f f") != std::string::npos);
    BOOST_TEST(walls.find("xplane 0.625") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_blend_gets_a_full_drop_height_of_headroom) {
    // Equal spheres: start_top + (start_top + 0.625) / 4 + 4 d, as the stored main set was
    // poured; a blend: start_top + (start_top + 0.625) + 4 d, since fines squeezed out
    // between coarse spheres fly higher than they fell.
    PourParams equal;
    equal.count = 1002;
    const double top = equal.cloud_top();
    BOOST_TEST(number(script_variable(pour_script(equal, top), "domain_top")) ==
                   top + 0.25 * (top + 0.625) + 4.0 * equal.diameter(),
               boost::test_tools::tolerance(1e-14));
    const PourParams blend = bimodal(1002);
    const double blend_top = blend.cloud_top();
    BOOST_TEST(number(script_variable(pour_script(blend, blend_top), "domain_top")) ==
                   2.0 * blend_top + 0.625 + 4.0 * blend.diameter(),
               boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(equal_spheres_keep_one_insertion) {
    PourParams p;
    p.count = 150;
    const std::string script = pour_script(p, p.cloud_top());
    BOOST_TEST(script.find("fix insert_cloud    all insert/pack seed") != std::string::npos);
    BOOST_TEST(script.find("particles_in_region ${count} region cloud") != std::string::npos);
    BOOST_TEST(number(script_variable(script, "radius")) == p.diameter() / 2.0);
}

BOOST_AUTO_TEST_CASE(blends_and_periodic_cells_are_refused_where_they_cannot_be_poured) {
    PourParams p = bimodal(300);
    p.sides = sgmp::Sides::Periodic;  // d_max = 0.378 > 1.25 / 4
    BOOST_CHECK_THROW(p.validate(), std::invalid_argument);
    p.count = 1002;
    BOOST_CHECK_NO_THROW(p.validate());
    p.arrangement = "loose-random";
    BOOST_CHECK_THROW(p.validate(), std::invalid_argument);
    p = bimodal(1002);
    p.fraction_basis = sgmp::FractionBasis::Mass;  // no densities
    BOOST_CHECK_THROW(p.validate(), std::invalid_argument);
    p = bimodal(1002);
    p.phi_target = 0.8;  // a blend may ask above the one-size bound
    BOOST_CHECK_NO_THROW(p.validate());
    p.size_modes = {{1.0, 0.5, 1.0}, {1.0, 0.5, 3.0}};  // one size, two densities
    BOOST_CHECK_THROW(p.validate(), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(densities_are_relative_to_species_one) {
    PourParams p = bimodal(1002);
    p.size_modes = {{1.0, 0.5}, {0.5, 0.5, 2.0}};  // species 1 without one: density 1
    p.fraction_basis = sgmp::FractionBasis::Volume;
    BOOST_TEST(p.species()[1].density == 2.0 * p.density);
    p.size_modes = {{1.0, 0.5, 2.0}, {0.5, 0.5}};  // species 2 without one: species 1's
    BOOST_TEST(p.species()[1].density == p.density);
}

BOOST_AUTO_TEST_SUITE_END()
