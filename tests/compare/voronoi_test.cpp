// Voronoi local packing fraction against cells known in advance: lattices whose cells are
// cubes, rhombic dodecahedra and truncated octahedra, hand-built clusters (including the
// radical plane of unequal spheres and cells cut by the cap), and the invariants of a
// tessellation (the cells fill the capped container; the particle order does not matter).
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "sgmp/metrics/measure.hpp"
#include "sgmp/metrics/parallel.hpp"
#include "sgmp/metrics/sphere_values.hpp"
#include "sgmp/metrics/voronoi.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/random.hpp"
#include "synthetic_packs.hpp"

using namespace sgmp;
using namespace sgmp::metrics;

namespace {

/// Lattice cells are computed in double precision from vertices a few ulps off the exact
/// ones: 1e-12 relative leaves three orders of magnitude of headroom.
constexpr double kExact = 1e-12;

/// Cubic lattice of side `a`, `n` conventional cells per axis, `basis` in units of a,
/// filling the container [0, n·a]² × [0, …) whose walls and floor are the cube's faces.
struct CubicLattice {
    std::vector<Particle> particles;
    Container container;
};
CubicLattice cubic_lattice(const std::vector<Vec3>& basis, double a, int n, double radius) {
    CubicLattice lattice;
    const double side = a * n;
    lattice.container = Container{0.0, side, 0.0, side, 0.0};
    std::int64_t id = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            for (int k = 0; k < n; ++k) {
                for (const Vec3& b : basis) {
                    const Vec3 c = a * (Vec3(i, j, k) + b);
                    lattice.particles.push_back(Particle{id++, c, radius, 0});
                }
            }
        }
    }
    return lattice;
}

/// Every cell in the region has φ = `phi`: mean = global = phi, sd ≈ 0, histogram spike.
void check_uniform(const VoronoiPhi& result, double phi, std::int64_t cells) {
    BOOST_TEST(result.cells == cells);
    BOOST_TEST(result.mean == phi, boost::test_tools::tolerance(kExact));
    BOOST_TEST(result.global == phi, boost::test_tools::tolerance(kExact));
    BOOST_TEST(result.sd < kExact * phi);
    BOOST_TEST(result.cap_cells == 0);
    const auto bin = static_cast<std::size_t>(phi * 100.0);
    BOOST_TEST(result.histogram.size() == 100U);
    BOOST_TEST(result.histogram[bin] == 100.0, boost::test_tools::tolerance(kExact));
}

/// A random pack without overlaps: radii in [0.5, 1]·r_max (equal when `equal`), centres
/// placed by random sequential addition in the thesis container's lower part.
std::vector<Particle> random_pack(std::size_t count, bool equal, unsigned seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double r_max = 0.04;
    const Container container;
    std::vector<Particle> particles;
    while (particles.size() < count) {
        const double r = equal ? r_max : r_max * (0.5 + 0.5 * unit(random));
        const Vec3 c(
            container.x_min + r + (container.x_max - container.x_min - 2 * r) * unit(random),
            container.floor + r + 1.0 * unit(random),
            container.z_min + r + (container.z_max - container.z_min - 2 * r) * unit(random));
        const bool free = std::none_of(particles.begin(), particles.end(), [&](const Particle& q) {
            return (q.center - c).norm() < q.radius + r;
        });
        if (free) {
            particles.push_back(Particle{static_cast<std::int64_t>(particles.size()), c, r, 0});
        }
    }
    return particles;
}

double cap_of(const std::vector<Particle>& particles) {
    double top = -1e300;
    double radius_sum = 0.0;
    for (const Particle& p : particles) {
        top = std::max(top, p.center.y() + p.radius);
        radius_sum += p.radius;
    }
    return top + 2.0 * radius_sum / static_cast<double>(particles.size());
}

Box everything(const Container& container) {
    return container.box_up_to(std::numeric_limits<double>::infinity());
}

}  // namespace

BOOST_AUTO_TEST_SUITE(voronoi)

BOOST_AUTO_TEST_CASE(simple_cubic_cells_are_cubes) {
    // Spheres of radius a/2 at (i + 1/2)·a: every cell below the top layer is the cube a³,
    // walls included (they lie a/2 from the centres), so φ = π/6.
    const double a = 0.1;
    const int n = 6;
    const auto lattice = cubic_lattice({Vec3(0.5, 0.5, 0.5)}, a, n, a / 2);
    const Box below_top{Vec3::Zero(), Vec3(n * a, (n - 1) * a, n * a)};
    check_uniform(voronoi_local_phi(lattice.particles, lattice.container, below_top),
                  std::numbers::pi / 6.0, n * n * (n - 1));
}

BOOST_AUTO_TEST_CASE(simple_cubic_top_layer_reaches_the_cap) {
    // The cap lies one diameter above the top of the top spheres, n·a + a: the top layer's
    // cells are a × a × 2a, φ = (π/6)/2 = π/12, and every one of them reaches the cap.
    const double a = 0.1;
    const int n = 6;
    const auto lattice = cubic_lattice({Vec3(0.5, 0.5, 0.5)}, a, n, a / 2);
    const Box top_layer{Vec3(0.0, (n - 1) * a, 0.0), Vec3(n * a, n * a, n * a)};
    const auto result = voronoi_local_phi(lattice.particles, lattice.container, top_layer);
    BOOST_TEST(result.cells == n * n);
    BOOST_TEST(result.mean == std::numbers::pi / 12.0, boost::test_tools::tolerance(kExact));
    BOOST_TEST(result.cap_cells == n * n);
}

BOOST_AUTO_TEST_CASE(fcc_cells_are_rhombic_dodecahedra) {
    // Touching spheres, r = a/(2√2); cells a³/4, φ = π/(3√2). Cells are complete for
    // centres more than a from every wall and the lattice's top (sites beyond a never
    // cut them).
    const double a = 0.1;
    const int n = 6;
    const Vec3 q = Vec3::Constant(0.25);
    const auto lattice = cubic_lattice(
        {q, q + Vec3(0.5, 0.5, 0.0), q + Vec3(0.5, 0.0, 0.5), q + Vec3(0.0, 0.5, 0.5)}, a, n,
        a / (2.0 * std::sqrt(2.0)));
    const Box interior{Vec3::Constant(1.1 * a), Vec3::Constant(4.9 * a)};
    // Sites at (m + 1/4)·a/2 per axis in [1.1 a, 4.9 a]: 8 per axis, half of them lattice sites.
    check_uniform(voronoi_local_phi(lattice.particles, lattice.container, interior),
                  std::numbers::pi / (3.0 * std::sqrt(2.0)), 8 * 8 * 8 / 2);
}

BOOST_AUTO_TEST_CASE(species_of_a_labelled_fcc_lattice_each_have_rhombic_dodecahedra) {
    // The FCC lattice above with its four basis sites labelled species 1, 2, 1, 2: every
    // cell is still a rhombic dodecahedron, so each species' mean and global φ is π/(3√2),
    // and the species' cells add up to the whole.
    const double a = 0.1;
    const Vec3 q = Vec3::Constant(0.25);
    auto lattice = cubic_lattice(
        {q, q + Vec3(0.5, 0.5, 0.0), q + Vec3(0.5, 0.0, 0.5), q + Vec3(0.0, 0.5, 0.5)}, a, 6,
        a / (2.0 * std::sqrt(2.0)));
    for (std::size_t i = 0; i < lattice.particles.size(); ++i) {
        lattice.particles[i].species = 1 + static_cast<int>(i % 2);
    }
    const Box interior{Vec3::Constant(1.1 * a), Vec3::Constant(4.9 * a)};
    const auto result = voronoi_local_phi(lattice.particles, lattice.container, interior);
    BOOST_TEST_REQUIRE(result.by_species.size() == 2u);
    std::int64_t cells = 0;
    for (const VoronoiSpecies& s : result.by_species) {
        BOOST_TEST(s.mean == std::numbers::pi / (3.0 * std::sqrt(2.0)),
                   boost::test_tools::tolerance(kExact));
        BOOST_TEST(s.global == std::numbers::pi / (3.0 * std::sqrt(2.0)),
                   boost::test_tools::tolerance(kExact));
        BOOST_TEST(s.sd < kExact);
        cells += s.cells;
    }
    BOOST_TEST(cells == result.cells);
}

BOOST_AUTO_TEST_CASE(bcc_cells_are_truncated_octahedra) {
    // Touching spheres, r = √3·a/4; cells a³/2, φ = π√3/8.
    const double a = 0.1;
    const int n = 6;
    const Vec3 q = Vec3::Constant(0.25);
    const auto lattice = cubic_lattice({q, q + Vec3::Constant(0.5)}, a, n, std::sqrt(3.0) * a / 4);
    const Box interior{Vec3::Constant(1.1 * a), Vec3::Constant(4.9 * a)};
    // Four whole cells per axis: 4³ conventional cells × 2 sites.
    check_uniform(voronoi_local_phi(lattice.particles, lattice.container, interior),
                  std::numbers::pi * std::sqrt(3.0) / 8.0, 4 * 4 * 4 * 2);
}

BOOST_AUTO_TEST_CASE(two_equal_spheres_split_the_box) {
    // Box [0, 2] × [0, cap] × [0, 1], cap = top 0.5 + d 0.5 = 1: each cell is half of it.
    const Container container{0.0, 2.0, 0.0, 1.0, 0.0};
    const std::vector<Particle> pair{{1, Vec3(0.5, 0.25, 0.5), 0.25, 0},
                                     {2, Vec3(1.5, 0.25, 0.5), 0.25, 0}};
    const auto result = voronoi_local_phi(pair, container, everything(container));
    const double sphere = 4.0 / 3.0 * std::numbers::pi * 0.25 * 0.25 * 0.25;
    BOOST_TEST(result.cells == 2);
    BOOST_TEST(result.cell_volume == 2.0, boost::test_tools::tolerance(kExact));
    BOOST_TEST(result.mean == sphere, boost::test_tools::tolerance(kExact));
    BOOST_TEST(result.global == sphere, boost::test_tools::tolerance(kExact));
    BOOST_TEST(result.cap_cells == 2);
}

BOOST_AUTO_TEST_CASE(unequal_spheres_meet_at_the_radical_plane) {
    // r = 0.3 at x = 0.5 and r = 0.2 at x = 1.5: (x − 0.5)² − 0.09 = (x − 1.5)² − 0.04 gives
    // x = 1.025 (the plain bisector would be 1). Cap = 0.6 + 0.5 = 1.1.
    const Container container{0.0, 2.0, 0.0, 1.0, 0.0};
    const std::vector<Particle> pair{{1, Vec3(0.5, 0.3, 0.5), 0.3, 0},
                                     {2, Vec3(1.5, 0.3, 0.5), 0.2, 0}};
    const double v1 = 1.025 * 1.1;
    const double v2 = 0.975 * 1.1;
    const double s1 = 4.0 / 3.0 * std::numbers::pi * 0.027;
    const double s2 = 4.0 / 3.0 * std::numbers::pi * 0.008;
    const auto left = voronoi_local_phi(pair, container, Box{Vec3::Zero(), Vec3(1.0, 1.0, 1.0)});
    BOOST_TEST(left.cells == 1);
    BOOST_TEST(left.cell_volume == v1, boost::test_tools::tolerance(kExact));
    BOOST_TEST(left.mean == s1 / v1, boost::test_tools::tolerance(kExact));
    const auto both = voronoi_local_phi(pair, container, everything(container));
    BOOST_TEST(both.cell_volume == v1 + v2, boost::test_tools::tolerance(kExact));
    BOOST_TEST(both.mean == (s1 / v1 + s2 / v2) / 2, boost::test_tools::tolerance(kExact));
    BOOST_TEST(both.global == (s1 + s2) / (v1 + v2), boost::test_tools::tolerance(kExact));
    // Population sd of two values: half their difference.
    BOOST_TEST(both.sd == std::abs(s1 / v1 - s2 / v2) / 2, boost::test_tools::tolerance(kExact));
}

BOOST_AUTO_TEST_CASE(local_phi_above_one_counts_in_the_last_bin) {
    // Four spheres of radius 0.1 overlapping 0.04 apart along x in a 0.16 × … × 0.2
    // container: cap 0.2 + 0.2, cells 0.04 × 0.4 × 0.2, φ = (4/3)π·10⁻³/0.0032 ≈ 1.309.
    const Container container{0.0, 0.16, 0.0, 0.2, 0.0};
    std::vector<Particle> row;
    for (int i = 0; i < 4; ++i) {
        row.push_back(Particle{i, Vec3(0.02 + 0.04 * i, 0.1, 0.1), 0.1, 0});
    }
    const auto result = voronoi_local_phi(row, container, everything(container));
    const double phi = 4.0 / 3.0 * std::numbers::pi * 1e-3 / (0.04 * 0.4 * 0.2);
    BOOST_TEST(result.mean == phi, boost::test_tools::tolerance(kExact));
    BOOST_TEST(result.histogram.back() == 100.0, boost::test_tools::tolerance(kExact));
}

BOOST_AUTO_TEST_CASE(cells_fill_the_capped_container) {
    // Σ V_i over all centres = container cross-section × (cap − floor). Summing ~10³
    // polyhedra in double precision: 1e-9 relative.
    const Container container;
    for (const bool equal : {true, false}) {
        const auto particles = random_pack(800, equal, 7);
        const auto result = voronoi_local_phi(particles, container, everything(container));
        const double volume = (container.x_max - container.x_min) *
                              (container.z_max - container.z_min) *
                              (cap_of(particles) - container.floor);
        BOOST_TEST(result.cells == 800);
        BOOST_TEST(result.cell_volume == volume, boost::test_tools::tolerance(1e-9));
        double integral = 0.0;
        for (const double h : result.histogram) {
            integral += h / static_cast<double>(result.histogram.size());
        }
        BOOST_TEST(integral == 1.0, boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(result_does_not_depend_on_particle_order) {
    // Bit-identical, not merely close: the kernel tessellates and sums in a canonical order.
    const Container container;
    for (const bool equal : {true, false}) {
        auto particles = random_pack(600, equal, 11);
        for (const Box& region : {control_volume(), everything(container)}) {
            const auto first = voronoi_local_phi(particles, container, region);
            std::mt19937_64 random(3);
            std::shuffle(particles.begin(), particles.end(), random);
            const auto second = voronoi_local_phi(particles, container, region);
            BOOST_TEST(first.cells == second.cells);
            BOOST_TEST(first.mean == second.mean);
            BOOST_TEST(first.sd == second.sd);
            BOOST_TEST(first.global == second.global);
            BOOST_TEST(first.cell_volume == second.cell_volume);
            BOOST_TEST(first.histogram == second.histogram);
        }
    }
}

BOOST_AUTO_TEST_CASE(result_does_not_depend_on_the_thread_count) {
    // 45,000 cells: enough for the kernel to split them between two or more containers.
    const Pack pack = sgmp::testing::jittered_fcc_pack(45000, 1.06, 0.015, 5);
    const Container container;
    VoronoiOptions options;
    options.threads = 1;
    const auto serial =
        voronoi_local_phi(pack.particles, container, everything(container), options);
    options.threads = 4;
    const auto threaded =
        voronoi_local_phi(pack.particles, container, everything(container), options);
    BOOST_TEST(serial.cells == 45000);
    BOOST_TEST(serial.mean == threaded.mean);
    BOOST_TEST(serial.sd == threaded.sd);
    BOOST_TEST(serial.global == threaded.global);
    BOOST_TEST(serial.cell_volume == threaded.cell_volume);
    BOOST_TEST(serial.cap_cells == threaded.cap_cells);
    BOOST_TEST(serial.histogram == threaded.histogram);
}

BOOST_AUTO_TEST_CASE(slabs_give_the_cells_of_the_whole_pack) {
    // One slab against slabs of 40 to 2000 cells, on a dense lattice and on a loose random
    // pack (cells reaching far, so many fail the neighbourhood test and are computed among
    // all centres): the same cells up to rounding, the cap cells and histogram exactly.
    const Container container;
    std::vector<std::vector<Particle>> packs{
        sgmp::testing::jittered_fcc_pack(6000, 1.06, 0.015, 9).particles};
    Random random(11);
    std::vector<Particle> loose(3000);
    for (std::size_t i = 0; i < loose.size(); ++i) {
        loose[i] = Particle{
            static_cast<std::int64_t>(i + 1),
            Vec3(random.uniform(-0.6, 0.6), random.uniform(-0.6, 0.6), random.uniform(-0.6, 0.6)),
            0.01, 0};
    }
    packs.push_back(loose);
    for (const auto& particles : packs) {
        VoronoiOptions whole;
        whole.cells_per_slab = particles.size();
        const auto one = voronoi_local_phi(particles, container, everything(container), whole);
        for (const std::size_t per_slab : {40u, 300u, 2000u}) {
            VoronoiOptions sliced;
            sliced.cells_per_slab = per_slab;
            const auto many =
                voronoi_local_phi(particles, container, everything(container), sliced);
            // Rounding of voro++'s plane cuts, which depend on the order it meets neighbours.
            const double tolerance = 1e-12;
            BOOST_TEST(many.cells == one.cells);
            BOOST_TEST(many.mean == one.mean, boost::test_tools::tolerance(tolerance));
            BOOST_TEST(many.sd == one.sd, boost::test_tools::tolerance(1e-9));
            BOOST_TEST(many.global == one.global, boost::test_tools::tolerance(tolerance));
            BOOST_TEST(many.cell_volume == one.cell_volume,
                       boost::test_tools::tolerance(tolerance));
            BOOST_TEST(many.cap_cells == one.cap_cells);
            BOOST_TEST(many.histogram == one.histogram);
        }
    }
}

BOOST_AUTO_TEST_CASE(bad_input_is_rejected_with_the_value_and_the_rule) {
    const Container container{0.0, 2.0, 0.0, 1.0, 0.0};
    const std::vector<Particle> pair{{1, Vec3(0.5, 0.25, 0.5), 0.25, 0},
                                     {2, Vec3(1.5, 0.25, 0.5), 0.25, 0}};
    const Box all = everything(container);
    const auto rejects = [](auto&& call, const std::string& words) {
        try {
            call();
        } catch (const std::invalid_argument& error) {
            const std::string message = error.what();
            BOOST_TEST_INFO("message: " << message);
            BOOST_TEST(message.find(words) != std::string::npos);
            return;
        }
        BOOST_FAIL("no std::invalid_argument for " + words);
    };
    rejects([&] { voronoi_local_phi({}, container, all); }, "no particles");
    auto negative = pair;
    negative[1].radius = -1.0;
    rejects([&] { voronoi_local_phi(negative, container, all); }, "radius -1 (must be positive");
    auto outside = pair;
    outside[0].center.x() = 2.5;
    rejects([&] { voronoi_local_phi(outside, container, all); }, "particle 1 has centre (2.5,");
    auto on_floor = pair;
    on_floor[1].center.y() = 0.0;
    rejects([&] { voronoi_local_phi(on_floor, container, all); }, "above the floor");
    rejects(
        [&] {
            voronoi_local_phi(pair, Container{1.0, 1.0, 0.0, 1.0, 0.0}, all);
        },
        "container '1 1 0 1 0' is empty");
    rejects(
        [&] {
            voronoi_local_phi(pair, container, Box{Vec3::Zero(), Vec3(0.0, 1.0, 1.0)});
        },
        "lo < hi");
    rejects(
        [&] {
            voronoi_local_phi(pair, container, Box{Vec3(1.9, 0.0, 0.0), Vec3(2.0, 1.0, 1.0)});
        },
        "holds no centre");
    rejects([&] { voronoi_local_phi(pair, container, all, VoronoiOptions{0}); },
            "histogram_bins = 0");
}

BOOST_AUTO_TEST_CASE(dem_pours_in_the_control_volume) {
    // The stored DEM pours of 3000 spheres: no control-volume cell reaches the cap, and the
    // mean local φ of a random pack lies between random loose and random close packing.
    for (const char* name : {"n3000-mu0.5-seed1.xyz.gz", "n3000-mu0.01-seed1.xyz.gz"}) {
        const auto path = std::filesystem::path(SGMP_SOURCE_DIR) / "data/reference" / name;
        const Pack pack = read_pack_file(path);
        const auto result = voronoi_local_phi(pack.particles, container_of(pack), control_volume());
        BOOST_TEST_INFO(name << ": mean " << result.mean << " sd " << result.sd << " global "
                             << result.global << " cells " << result.cells);
        BOOST_TEST(result.cap_cells == 0);
        BOOST_TEST(result.mean > 0.55);
        BOOST_TEST(result.mean < 0.66);
        BOOST_TEST(result.sd > 0.0);
    }
}

// Per-sphere values of `sgmp render --colour z|local-phi` (sphere_values.hpp): Z_i(δ) on
// the kd-tree against a brute count over all pairs, at δ = 0 and 10⁻³ (and a gap of
// 0.02·d that takes in the near neighbours of random sequential addition); φ_i against the
// tessellation's own statistics: their mean and sd over every centre are voronoi_phi_mean
// and _sd of the same pack (to rounding of the two summation orders).
BOOST_AUTO_TEST_CASE(sphere_values_match_a_brute_count_and_the_tessellation) {
    for (const unsigned seed : {1U, 2U, 3U}) {
        const auto particles = random_pack(400, seed == 2, seed);
        double radius_sum = 0.0;
        for (const Particle& p : particles) {
            radius_sum += p.radius;
        }
        const double d = 2.0 * radius_sum / static_cast<double>(particles.size());
        for (const double gap : {0.0, 1e-3, 0.02, 0.3}) {
            const auto z = metrics::sphere_contact_numbers(particles, Container{}, gap);
            BOOST_TEST_REQUIRE(z.size() == particles.size());
            std::size_t differ = 0;
            double total = 0.0;
            for (std::size_t i = 0; i < particles.size(); ++i) {
                int brute = 0;
                for (std::size_t j = 0; j < particles.size(); ++j) {
                    const Particle &a = particles[i], &b = particles[j];
                    brute +=
                        j != i && (a.center - b.center).norm() - a.radius - b.radius <= gap * d;
                }
                differ += z[i] != brute;
                total += z[i];
            }
            BOOST_TEST(differ == 0U);
            if (gap == 0.3) {
                BOOST_TEST(total > 0.0);  // the test compares non-trivial counts
            }
        }
        const Container container;
        const auto phi = metrics::sphere_local_phi(particles, container);
        const auto all = metrics::voronoi_local_phi(particles, container, everything(container));
        double sum = 0.0, square = 0.0;
        for (const double v : phi) {
            sum += v;
        }
        const double mean = sum / static_cast<double>(phi.size());
        for (const double v : phi) {
            square += (v - mean) * (v - mean);
        }
        BOOST_TEST(mean == all.mean, boost::test_tools::tolerance(1e-12));
        BOOST_TEST(std::sqrt(square / static_cast<double>(phi.size())) == all.sd,
                   boost::test_tools::tolerance(1e-9));
    }
}

BOOST_AUTO_TEST_SUITE_END()
