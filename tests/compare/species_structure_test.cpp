// Per-species structure of blends: partial g_IJ(r) and Z_IJ(δ) on a rock-salt lattice (known
// answers), against brute force on a random binary pack, independent of the thread count,
// and through measure().
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include "sgmp/metrics/measure.hpp"
#include "sgmp/metrics/parallel.hpp"
#include "sgmp/metrics/species_structure.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;
using namespace sgmp::metrics;

namespace {

Particle sphere(std::int64_t id, const Vec3& c, double r, int species) {
    Particle p;
    p.id = id;
    p.center = c;
    p.radius = r;
    p.species = species;
    return p;
}

/// Rock salt with cube side a: species 1 (radius r1) where i + j + k is even, species 2
/// (radius r2) where it is odd, sites (i, j, k)·a/2 inside the cube [-h, h]³.
std::vector<Particle> rock_salt(double a, double r1, double r2, double h) {
    std::vector<Particle> particles;
    const int n = static_cast<int>(std::floor(2.0 * h / a));
    for (int i = -n; i <= n; ++i) {
        for (int j = -n; j <= n; ++j) {
            for (int k = -n; k <= n; ++k) {
                const bool even = (i + j + k) % 2 == 0;
                particles.push_back(sphere(static_cast<std::int64_t>(particles.size() + 1),
                                           Vec3(i, j, k) * (0.5 * a), even ? r1 : r2,
                                           even ? 1 : 2));
            }
        }
    }
    return particles;
}

SpeciesStructureOptions options_for(const std::vector<Particle>& particles, double region_half,
                                    double space_half) {
    SpeciesStructureOptions o;
    o.region = Box{Vec3::Constant(-region_half), Vec3::Constant(region_half)};
    o.space = Box{Vec3::Constant(-space_half), Vec3::Constant(space_half)};
    double sum = 0.0;
    for (const Particle& p : particles) {
        sum += p.radius;
    }
    o.mean_diameter = 2.0 * sum / static_cast<double>(particles.size());
    o.bin_width_over_d = 0.02;
    o.bins = 151;
    o.tolerances = {1e-6, 1e-3, 5e-2};
    return o;
}

const SpeciesPair& pair_of(const SpeciesStructure& s, int i, int j) {
    for (const SpeciesPair& p : s.pairs) {
        if (p.i == i && p.j == j) {
            return p;
        }
    }
    throw std::logic_error("no such pair type");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(species_structure)

BOOST_AUTO_TEST_CASE(rock_salt_has_six_unlike_contacts_and_twelve_like_second_neighbours) {
    // a = 0.1, r1 + r2 = a/2: every sphere touches its six unlike neighbours; like
    // neighbours sit at a/√2 = 0.0707 > 2·r1 = 0.06, so Z_11 = Z_22 = 0 at every tolerance
    // up to 5·10⁻² d (gap 0.0107 = 0.21 d).
    const double a = 0.1;
    const auto particles = rock_salt(a, 0.03, 0.02, 0.6);
    const auto o = options_for(particles, 0.2, 0.7);  // origins 4 a from every edge
    const auto s = measure_species_structure(particles, o);
    BOOST_TEST_REQUIRE(s.has_value());
    BOOST_TEST(s->species.size() == 2u);
    BOOST_TEST(s->pairs.size() == 3u);
    const auto& unlike = pair_of(*s, 1, 2);
    const auto& ones = pair_of(*s, 1, 1);
    const auto& twos = pair_of(*s, 2, 2);
    for (std::size_t t = 0; t < 3; ++t) {
        BOOST_TEST(unlike.z_ij[t] == 6.0);
        BOOST_TEST(unlike.z_ji[t] == 6.0);
        BOOST_TEST(ones.z_ij[t] == 0.0);
        BOOST_TEST(twos.z_ij[t] == 0.0);
        BOOST_TEST(s->species[0].z_mean[t] == 6.0);
        BOOST_TEST(s->species[1].z_mean[t] == 6.0);
    }
    // The contact distance a/2 is a bin centre: all six unlike contacts in one bin.
    const double width = o.bin_width_over_d * o.mean_diameter;
    const auto n1 = static_cast<std::int64_t>(s->species[0].origins);
    const auto contact_bin = static_cast<std::size_t>(std::llround(0.5 * a / width));
    BOOST_TEST(unlike.pairs[contact_bin] == 6 * n1);
    BOOST_TEST(std::abs(unlike.bin_offset_over_d * o.mean_diameter) <= 0.5 * width);
    // Twelve like neighbours at a/√2 in species 1's own bins.
    const double second = a / std::sqrt(2.0);
    const auto like_bin = static_cast<std::size_t>(
        std::floor((second - ones.bin_offset_over_d * o.mean_diameter) / width + 0.5));
    BOOST_TEST(ones.pairs[like_bin] == 12 * n1);
    std::int64_t closer = 0;
    for (std::size_t k = 0; k < like_bin; ++k) {
        closer += ones.pairs[k];
    }
    BOOST_TEST(closer == 0);
}

BOOST_AUTO_TEST_CASE(pair_counts_and_contacts_equal_brute_force) {
    // 900 spheres of three species (radii 0.02, 0.012, 0.012 with a second species of
    // two radii, so its pair types keep bin offset 0) placed at random in a box: every pair
    // type's bin counts and Z_IJ at every tolerance against an O(N²) loop written here.
    Random random(21);
    std::vector<Particle> particles;
    for (int i = 0; i < 900; ++i) {
        const int species = 1 + i % 3;
        const double r = species == 1 ? 0.02 : species == 2 ? (i % 2 == 0 ? 0.012 : 0.011) : 0.012;
        particles.push_back(sphere(
            i + 1,
            Vec3(random.uniform(-0.3, 0.3), random.uniform(-0.3, 0.3), random.uniform(-0.3, 0.3)),
            r, species));
    }
    const auto o = options_for(particles, 0.15, 0.3);
    const auto s = measure_species_structure(particles, o);
    BOOST_TEST_REQUIRE(s.has_value());
    const double d = o.mean_diameter;
    const double width = o.bin_width_over_d * d;
    for (const SpeciesPair& pair : s->pairs) {
        const double offset = pair.bin_offset_over_d * d;
        std::vector<std::int64_t> bins(o.bins, 0);
        std::map<std::pair<int, int>, std::vector<std::int64_t>> contacts;
        const std::vector<int> froms =
            pair.i == pair.j ? std::vector<int>{pair.i} : std::vector<int>{pair.i, pair.j};
        for (const int from : froms) {
            const int to = from == pair.i ? pair.j : pair.i;
            auto& z = contacts[{from, to}];
            z.assign(o.tolerances.size(), 0);
            for (std::size_t a = 0; a < particles.size(); ++a) {
                if (particles[a].species != from || !o.region.contains(particles[a].center)) {
                    continue;
                }
                for (std::size_t b = 0; b < particles.size(); ++b) {
                    if (b == a || particles[b].species != to) {
                        continue;
                    }
                    const double distance = (particles[a].center - particles[b].center).norm();
                    const double gap = distance - particles[a].radius - particles[b].radius;
                    for (std::size_t t = 0; t < o.tolerances.size(); ++t) {
                        z[t] += gap <= o.tolerances[t] * d ? 1 : 0;
                    }
                    if (from == pair.i) {
                        const double u = (distance - offset) / width + 0.5;
                        const auto k = u < 1.0 ? 0u : static_cast<std::size_t>(u);
                        if (k < bins.size()) {
                            ++bins[k];
                        }
                    }
                }
            }
        }
        BOOST_TEST(pair.pairs == bins, boost::test_tools::per_element());
        const auto origins_of = [&](int species) {
            return static_cast<double>(s->species[static_cast<std::size_t>(species - 1)].origins);
        };
        for (std::size_t t = 0; t < o.tolerances.size(); ++t) {
            BOOST_TEST(pair.z_ij[t] ==
                       static_cast<double>(contacts[{pair.i, pair.j}][t]) / origins_of(pair.i));
            BOOST_TEST(pair.z_ji[t] ==
                       static_cast<double>(contacts[{pair.j, pair.i}][t]) / origins_of(pair.j));
        }
        // Far from contact the partials approach 1 (neighbours' density rule).
        if (pair.i != 2 && pair.j != 2) {
            BOOST_TEST(std::abs(pair.bin_offset_over_d) <= 0.5 * o.bin_width_over_d);
        } else {
            BOOST_TEST(pair.bin_offset_over_d == 0.0);  // a species of two radii
        }
    }
}

BOOST_AUTO_TEST_CASE(results_do_not_depend_on_the_thread_count) {
    const auto particles = rock_salt(0.1, 0.031, 0.019, 0.5);
    auto o = options_for(particles, 0.3, 0.6);
    o.threads = 1;
    const auto one = measure_species_structure(particles, o);
    o.threads = 2;
    const auto two = measure_species_structure(particles, o);
    for (std::size_t p = 0; p < one->pairs.size(); ++p) {
        BOOST_TEST(one->pairs[p].pairs == two->pairs[p].pairs, boost::test_tools::per_element());
        BOOST_TEST(one->pairs[p].g == two->pairs[p].g, boost::test_tools::per_element());
    }
}

BOOST_AUTO_TEST_CASE(one_species_gives_none_and_measure_gives_a_blends) {
    auto particles = rock_salt(0.1, 0.03, 0.02, 0.3);
    for (auto& p : particles) {
        p.species = 0;
    }
    BOOST_TEST(!measure_species_structure(particles, options_for(particles, 0.1, 0.4)));
    // Through measure(): a blend in the thesis container gets the partials.
    Pack pack;
    Random random(3);
    for (int i = 0; i < 400; ++i) {
        pack.particles.push_back(
            sphere(i + 1,
                   Vec3(random.uniform(-0.55, 0.55), random.uniform(-0.55, 0.55),
                        random.uniform(-0.55, 0.55)),
                   i % 2 == 0 ? 0.03 : 0.015, 1 + i % 2));
    }
    MeasureOptions options;
    options.voronoi = false;
    const Measurement m = measure(pack, options);
    BOOST_TEST_REQUIRE(m.species.has_value());
    BOOST_TEST(m.species->pairs.size() == 3u);
    BOOST_TEST(m.species->pairs[0].g.size() == m.local.rdf.g.size());
    for (const SpeciesPair& pair : m.species->pairs) {
        for (const double g : pair.g) {
            BOOST_TEST(g >= 0.0);  // never a negative g
        }
    }
    // φ(y) by species adds up to φ(y) (exact volumes: rounding only).
    BOOST_TEST_REQUIRE(m.phi_profile_by_species.size() == 2u);
    for (std::size_t k = 0; k < m.phi_profile.phi.size(); ++k) {
        const double sum = m.phi_profile_by_species[0].phi[k] + m.phi_profile_by_species[1].phi[k];
        BOOST_TEST(std::abs(sum - m.phi_profile.phi[k]) <= 1e-12);
    }
}

BOOST_AUTO_TEST_SUITE_END()
