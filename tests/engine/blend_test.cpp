// Blends as users state them: size-distribution files, fraction bases, deterministic
// species counts, species on every particle and the realised fractions in the header.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <map>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/random.hpp"
#include "sgmp/pack/size_modes.hpp"
#include "test_support.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

/// The propellant-like blend of coarse AP 400 µm, fine AP 20 µm and Al 30 µm at mass
/// fractions 51 : 17 : 18 (the rest is binder), densities 1.95 and 2.70 g/cm³.
const char* kPropellant =
    "# coarse AP, fine AP, aluminium\n"
    "density,diameter,fraction\n"
    "1.95,400,0.51\n"
    "1.95,20,0.17\n\n"
    "2.70,30,0.18\n";

std::string csv_error(const std::string& text) {
    return testing::input_error_of([&] { parse_size_distribution_csv(text, "blend.csv"); });
}

}  // namespace

BOOST_AUTO_TEST_SUITE(blends)

BOOST_AUTO_TEST_CASE(a_distribution_file_reads_in_any_column_order) {
    const auto modes = parse_size_distribution_csv(kPropellant, "blend.csv");
    BOOST_TEST_REQUIRE(modes.size() == 3u);
    // Diameters over the largest: only ratios matter.
    BOOST_TEST(modes[0].relative_diameter == 1.0);
    BOOST_TEST(modes[1].relative_diameter == 20.0 / 400.0);
    BOOST_TEST(modes[2].relative_diameter == 30.0 / 400.0);
    BOOST_TEST(modes[2].fraction == 0.18);
    BOOST_TEST(*modes[2].density == 2.70);
}

BOOST_AUTO_TEST_CASE(bad_files_name_the_line_and_the_rule) {
    BOOST_TEST(csv_error("diameter,fraction,colour\n1,1,2\n") ==
               "blend.csv:1: unknown column 'colour': the columns are diameter (or "
               "diameter_UNIT, UNIT one of m, cm, mm, um, nm), fraction and optionally density");
    BOOST_TEST(csv_error("diameter\n1\n").find("blend.csv:1: the header must name") == 0u);
    BOOST_TEST(csv_error("diameter,fraction\n0,1\n") ==
               "blend.csv:2: diameter 0: a diameter must be greater than 0");
    BOOST_TEST(csv_error("diameter,fraction\n1,-0.1\n") ==
               "blend.csv:2: fraction -0.1: a fraction must not be negative");
    BOOST_TEST(csv_error("diameter,fraction\n1,0\n2,0\n") ==
               "blend.csv:3: every fraction is 0: at least one must be positive");
    BOOST_TEST(csv_error("diameter,fraction,density\n1,1,0\n") ==
               "blend.csv:2: density 0: a density must be greater than 0");
    BOOST_TEST(csv_error("diameter,fraction\n1,nan\n") ==
               "blend.csv:2: fraction 'nan' is not a finite number");
    BOOST_TEST(csv_error("diameter,fraction\n1,1,1\n") ==
               "blend.csv:2: has 3 fields, the header 2");
    BOOST_TEST(csv_error("diameter,fraction\n").find("holds no species row") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(fractions_convert_between_bases_by_closed_form) {
    // Volume fractions v_i of diameters a_i: n_i ∝ v_i / a_i³; mass m_i: n_i ∝ m_i/(ρ_i a_i³).
    const std::vector<SizeMode> modes{{1.0, 0.5, 2.0}, {0.5, 0.5, 1.0}};
    const auto by_volume = number_fractions(modes, FractionBasis::Volume);
    const double n0 = 0.5 / 1.0, n1 = 0.5 / 0.125;  // 0.5, 4
    BOOST_TEST(by_volume[0].fraction == n0 / (n0 + n1), boost::test_tools::tolerance(1e-15));
    BOOST_TEST(by_volume[1].fraction == n1 / (n0 + n1), boost::test_tools::tolerance(1e-15));
    const auto by_mass = number_fractions(modes, FractionBasis::Mass);
    const double m0 = 0.5 / (2.0 * 1.0), m1 = 0.5 / (1.0 * 0.125);  // 0.25, 4
    BOOST_TEST(by_mass[0].fraction == m0 / (m0 + m1), boost::test_tools::tolerance(1e-15));
    const auto by_number = number_fractions(modes, FractionBasis::Number);
    BOOST_TEST(by_number[0].fraction == 0.5);
    BOOST_CHECK_THROW(number_fractions({{1.0, 1.0}, {0.5, 1.0}}, FractionBasis::Mass),
                      ParameterError);
}

BOOST_AUTO_TEST_CASE(counts_are_within_one_particle_of_the_request_over_many_draws) {
    // Invariant over 2000 random blends: each count within one of n_i·N, and they sum to N.
    Random rng(11);
    for (int trial = 0; trial < 2000; ++trial) {
        const std::size_t n = 1 + rng.below(5000);
        std::vector<SizeMode> modes;
        const std::size_t k = 1 + rng.below(6);
        double total = 0.0;
        for (std::size_t i = 0; i < k; ++i) {
            modes.emplace_back(rng.uniform(0.05, 1.0), rng.uniform(0.0, 1.0));
            total += modes.back().fraction;
        }
        const auto counts = mode_counts(n, modes);
        std::size_t sum = 0;
        for (std::size_t i = 0; i < k; ++i) {
            const double wanted = static_cast<double>(n) * modes[i].fraction / total;
            BOOST_TEST(std::abs(static_cast<double>(counts[i]) - wanted) < 1.0);
            sum += counts[i];
        }
        BOOST_TEST(sum == n);
    }
}

BOOST_AUTO_TEST_CASE(a_blend_pack_carries_species_and_its_realised_fractions) {
    PackRequest request;
    request.count = 2000;
    request.arrangement = Arrangement::LooseRandom;
    request.seed = 4;
    request.size_modes = {{1.0, 0.6}, {0.5, 0.4}};
    request.fraction_basis = FractionBasis::Volume;
    request.size_distribution = "two.csv";
    const Pack pack = make_pack(request);
    // Number fractions from the volume ones: 0.6 : 0.4/0.125 = 0.6 : 3.2.
    const double n1 = 2000.0 * 0.6 / 3.8;
    std::map<int, std::size_t> counts;
    std::map<int, double> radius;
    for (const Particle& p : pack.particles) {
        ++counts[p.species];
        if (radius.count(p.species) == 0) {
            radius[p.species] = p.radius;
        }
        BOOST_TEST(p.radius == radius[p.species]);  // one size per species
    }
    BOOST_TEST_REQUIRE(counts.size() == 2u);
    BOOST_TEST(std::abs(static_cast<double>(counts[1]) - n1) < 1.0);
    BOOST_TEST(counts[1] + counts[2] == 2000u);
    BOOST_TEST(radius[2] == 0.5 * radius[1]);
    BOOST_TEST(*pack.metadata.get("fraction_basis") == "volume");
    BOOST_TEST(*pack.metadata.get("size_distribution") == "two.csv");
    BOOST_TEST(*pack.metadata.get("species_counts") ==
               std::to_string(counts[1]) + "," + std::to_string(counts[2]));
    // Realised volume fractions from the counts, recomputed here.
    const double v1 = static_cast<double>(counts[1]);
    const double v2 = static_cast<double>(counts[2]) * 0.125;
    const std::string volume = *pack.metadata.get("species_volume_fractions");
    BOOST_TEST(std::stod(volume.substr(0, volume.find(','))) == v1 / (v1 + v2),
               boost::test_tools::tolerance(1e-12));
    BOOST_TEST(!pack.metadata.contains("species_mass_fractions"));  // no densities given
}

BOOST_AUTO_TEST_CASE(one_species_packs_keep_their_bytes_and_the_thesis_bound) {
    PackRequest request;
    request.count = 200;
    request.arrangement = Arrangement::LooseRandom;
    const Pack pack = make_pack(request);
    BOOST_TEST(std::all_of(pack.particles.begin(), pack.particles.end(),
                           [](const Particle& p) { return p.species == 0; }));
    BOOST_TEST(!pack.metadata.contains("species_counts"));
    BOOST_TEST(!pack.metadata.contains("fraction_basis"));
    request.phi_target = 0.8;
    BOOST_CHECK_THROW(validate(request), ParameterError);  // equal spheres: ≤ 0.74048
    request.size_modes = {{1.0, 0.5}, {0.1, 0.5}};
    BOOST_CHECK_NO_THROW(validate(request));  // a blend may pack denser
    request.phi_target = 1.0;
    BOOST_CHECK_THROW(validate(request), ParameterError);
}

BOOST_AUTO_TEST_SUITE_END()
