#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "refusal.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/size_modes.hpp"

using namespace sgmp;
using namespace sgmp::engine;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_SUITE(size_modes)

BOOST_AUTO_TEST_CASE(modes_parse_and_print) {
    const auto modes = parse_size_modes("1:0.7,0.5:0.3");
    BOOST_TEST_REQUIRE(modes.has_value());
    BOOST_TEST(modes->size() == 2u);
    BOOST_TEST((*modes)[1].relative_diameter == 0.5);
    BOOST_TEST((*modes)[1].fraction == 0.3);
    BOOST_TEST(size_modes_to_string(*modes) == "1:0.7,0.5:0.3");
    BOOST_TEST(is_monodisperse(*parse_size_modes("1:1")));
    BOOST_TEST(!is_monodisperse(*modes));
    for (const char* bad : {"", "1", "1:", ":1", "1:0", "-1:1", "1:1,", "1:1;2:1", "a:1"}) {
        BOOST_TEST_INFO(bad);
        BOOST_TEST(!parse_size_modes(bad).has_value());
    }
}

BOOST_AUTO_TEST_CASE(lognormal_classes_sit_at_their_own_median_quantiles) {
    // D_k = MEDIAN·exp(SIGMA·Φ⁻¹(p_k)), p_k = QLO + (k + ½)(QHI − QLO)/CLASSES, with Φ⁻¹ found
    // here by bisection on Φ(x) = ½·erfc(−x/√2) (std::erfc, 200 halvings): relative
    // diameters D_k / D_last agree to 1e-12, fractions are equal, species increase in size.
    const auto modes = lognormal_modes("lognormal:200:0.45:7:0.02:0.97");
    BOOST_TEST_REQUIRE(modes.size() == 7u);
    const auto inverse_normal = [](double p) {
        double lo = -40.0;
        double hi = 40.0;
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (lo + hi);
            (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
    };
    std::vector<double> expected;
    for (int k = 0; k < 7; ++k) {
        expected.push_back(200.0 *
                           std::exp(0.45 * inverse_normal(0.02 + (k + 0.5) * (0.97 - 0.02) / 7)));
    }
    for (std::size_t k = 0; k < 7; ++k) {
        BOOST_TEST(modes[k].relative_diameter == expected[k] / expected.back(),
                   tt::tolerance(1e-12));
        BOOST_TEST(modes[k].fraction == 1.0 / 7.0);
        if (k > 0) {
            BOOST_TEST(modes[k].relative_diameter > modes[k - 1].relative_diameter);
        }
    }
    BOOST_TEST(lognormal_modes("lognormal:1:0.2").size() == 10u);  // the default classes
    for (const char* bad :
         {"lognormal:0:0.2", "lognormal:1:0", "lognormal:1:4", "lognormal:1:0.2:2.5",
          "lognormal:1:0.2:3:0.9:0.1", "lognormal:1:0.2:3:0.1", "lognormal:x:1",
          "lognormal:1:0.2:1001", "normal:1:1"}) {
        BOOST_CHECK_THROW(lognormal_modes(bad), ParameterError);
    }
}

BOOST_AUTO_TEST_CASE(the_scale_fills_a_third_into_the_control_volume) {
    // Monodisperse: the thesis rule.
    BOOST_TEST(diameter_scale(1002, 0.63, {SizeMode{}}) == diameter_for_count(1002, 0.63),
               tt::tolerance(1e-14));
    // Bimodal: (N/3)(π/6) Σ f_i (a_i s)³ = φ*, fractions normalised (0.7 + 0.3 = 1 here
    // written as 7:3).
    const std::vector<SizeMode> modes = {SizeMode{1.0, 7.0}, SizeMode{0.5, 3.0}};
    const double s = diameter_scale(900, 0.6, modes);
    const double volume =
        300.0 * std::numbers::pi / 6.0 * (0.7 * s * s * s + 0.3 * std::pow(0.5 * s, 3));
    BOOST_TEST(volume == 0.6, tt::tolerance(1e-13));
}

BOOST_AUTO_TEST_CASE(a_stratified_order_keeps_every_prefix_within_one_particle) {
    // Brute force over every prefix k: |p_i(k) - k·n_i/N| < 1 for each species i, and the
    // sequence holds exactly n_i of each (integers compared as k·n_i - p_i·N against N).
    for (const std::vector<std::size_t>& counts : std::vector<std::vector<std::size_t>>{
             {333, 2667}, {82, 1762, 8156}, {1, 1, 1}, {7, 0, 5}, {1, 999}, {500, 300, 200, 1}}) {
        const std::vector<std::size_t> sequence = stratified_sequence(counts);
        const long long total = std::accumulate(counts.begin(), counts.end(), 0LL);
        BOOST_TEST(static_cast<long long>(sequence.size()) == total);
        std::vector<long long> placed(counts.size(), 0);
        long long worst = 0;  // max over k, i of |k·n_i - p_i·N|, must stay below N
        for (std::size_t k = 1; k <= sequence.size(); ++k) {
            ++placed[sequence[k - 1]];
            for (std::size_t i = 0; i < counts.size(); ++i) {
                const long long gap =
                    static_cast<long long>(k) * static_cast<long long>(counts[i]) -
                    placed[i] * total;
                worst = std::max(worst, gap < 0 ? -gap : gap);
            }
        }
        BOOST_TEST(worst < total);
        for (std::size_t i = 0; i < counts.size(); ++i) {
            BOOST_TEST(placed[i] == static_cast<long long>(counts[i]));
        }
    }
}

BOOST_AUTO_TEST_CASE(a_stratified_draw_uses_no_random_numbers) {
    const std::vector<SizeMode> modes = {SizeMode{1.0, 0.1}, SizeMode{0.5, 0.9}};
    Random a(3);
    Random b(3);
    const DrawnSizes drawn = draw_sizes(1000, 0.63, modes, a, DropOrder::Stratified);
    BOOST_TEST(a.raw() == b.raw());
    BOOST_TEST(std::count(drawn.species.begin(), drawn.species.end(), 1) == 100);
    BOOST_TEST(drawn.species[0] == 2);  // deficits 0.1 and 0.9 at k = 1
}

BOOST_AUTO_TEST_CASE(diameters_follow_the_fractions_in_random_order) {
    const std::vector<SizeMode> modes = {SizeMode{1.0, 0.5}, SizeMode{0.5, 0.3},
                                         SizeMode{0.25, 0.2}};
    Random rng(1);
    const auto d = draw_diameters(1001, 0.63, modes, rng);
    const double s = diameter_scale(1001, 0.63, modes);
    BOOST_TEST(d.size() == 1001u);
    // Shares 500.5, 300.3, 200.2: floors 500, 300, 200, the last one to the largest remainder.
    BOOST_TEST(std::count(d.begin(), d.end(), s) == 501);
    BOOST_TEST(std::count(d.begin(), d.end(), 0.5 * s) == 300);
    BOOST_TEST(std::count(d.begin(), d.end(), 0.25 * s) == 200);
    BOOST_TEST(!std::is_sorted(d.begin(), d.end()));
    // A single mode draws nothing from the generator.
    Random a(9);
    Random b(9);
    draw_diameters(50, 0.63, {SizeMode{}}, a);
    BOOST_TEST(a.raw() == b.raw());
}

BOOST_AUTO_TEST_CASE(a_multi_modal_pack_records_its_modes_and_sizes) {
    PackRequest request;
    request.count = 400;
    request.arrangement = Arrangement::LooseRandom;
    request.size_modes = {SizeMode{1.0, 0.5}, SizeMode{0.4, 0.5}};
    const Pack pack = make_pack(request);
    BOOST_TEST(pack.metadata.get("size_modes").value_or("") == "1:0.5,0.4:0.5");
    const double s = *pack.metadata.get_number("diameter");
    std::size_t small = 0;
    for (const Particle& p : pack.particles) {
        BOOST_TEST((p.radius == s / 2 || p.radius == 0.2 * s));
        small += p.radius < s / 2 ? 1 : 0;
    }
    BOOST_TEST(small == 200u);
    request.size_modes = {SizeMode{1.0, 0.5}, SizeMode{0.0, 0.5}};
    BOOST_TEST(refusal([&] { validate(request); }).find("--size-modes") == 0u);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(start_pack_sizes)

// The reference pours from the engine's starting arrangements (make_start_pack) with the
// diameter of the sizing rule: for one size mode the two must be the same number, bit
// for bit, or a pour's spheres would differ from the arrangement's by rounding.
BOOST_AUTO_TEST_CASE(one_mode_gives_exactly_the_sizing_rule_diameter) {
    for (const std::size_t n : {150u, 300u, 750u, 1002u, 2001u, 3000u, 6000u, 9000u, 100000u}) {
        for (const double phi : {0.3, 0.63, sgmp::kMaxPhiTarget}) {
            BOOST_TEST(sgmp::diameter_scale(n, phi, {sgmp::SizeMode{1.0, 1.0}}) ==
                       sgmp::diameter_for_count(n, phi));
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
