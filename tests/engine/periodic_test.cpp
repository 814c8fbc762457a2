// Periodic sides (`--sides periodic`, sides.hpp): over arrangements, contact models, blends
// and seeds, a brute-force minimum-image check of every pair finds no overlap beyond
// rounding (1e-12·d), every centre lies in the cell, spheres touch across the faces,
// check_pack's support count on its periodic cell grid equals a brute-force count, the
// floor is the only wall, and the same request gives the same pack. A wall pack keeps its
// header without a `sides` key. Relaxed periodic packs (both modes) keep the same checks
// and are certified, with contacts across the faces. Periodic sides refuse spheres wider
// than a quarter of the cell (exit 2 in the CLI tests' sense: ParameterError).
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/engine/pack_checks.hpp"
#include "sgmp/engine/protocol.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/random.hpp"
#include "sgmp/pack/size_classes.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

struct Periodic {
    double min_gap_over_d = INFINITY;
    std::size_t across = 0;  ///< pairs touching (gap ≤ 1e-9·d) only through a face
    bool inside = true;
    /// Spheres neither within 1e-9·d of the floor or a face nor within 1e-9·d of a sphere
    /// whose centre is not higher (minimum image): check_pack's `unsupported`.
    std::size_t unsupported = 0;
};

Periodic brute_force(const Pack& pack, double d) {
    const Container c;  // the cell: the container's x and z ranges
    const double lx = c.x_max - c.x_min, lz = c.z_max - c.z_min;
    Periodic out;
    const auto& p = pack.particles;
    const double tolerance = 1e-9 * d;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec3& a = p[i].center;
        const double r = p[i].radius;
        bool supported = a.y() - r - c.floor <= tolerance || a.x() - r - c.x_min <= tolerance ||
                         c.x_max - a.x() - r <= tolerance || a.z() - r - c.z_min <= tolerance ||
                         c.z_max - a.z() - r <= tolerance;
        for (std::size_t j = 0; j < p.size() && !supported; ++j) {
            Vec3 delta = p[j].center - a;
            delta.x() -= lx * std::round(delta.x() / lx);
            delta.z() -= lz * std::round(delta.z() / lz);
            supported =
                j != i && p[j].center.y() <= a.y() && delta.norm() - r - p[j].radius <= tolerance;
        }
        out.unsupported += supported ? 0 : 1;
        out.inside = out.inside && a.x() >= c.x_min && a.x() < c.x_max && a.z() >= c.z_min &&
                     a.z() < c.z_max && a.y() - p[i].radius >= c.floor - 1e-12 * d;
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            Vec3 delta = p[j].center - a;
            const double direct = delta.norm();
            delta.x() -= lx * std::round(delta.x() / lx);
            delta.z() -= lz * std::round(delta.z() / lz);
            const double gap = delta.norm() - p[i].radius - p[j].radius;
            out.min_gap_over_d = std::min(out.min_gap_over_d, gap / d);
            if (gap <= 1e-9 * d && std::abs(direct - delta.norm()) > 1e-9 * d) {
                ++out.across;
            }
        }
    }
    return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(periodic_packs_have_no_overlap_under_the_minimum_image) {
    for (const Arrangement arrangement : {Arrangement::LooseRandom, Arrangement::SmallDense}) {
        for (const ContactModel contact :
             {ContactModel::None, ContactModel::Settle, ContactModel::Roll}) {
            for (const std::uint64_t seed : {1U, 2U}) {
                for (const bool blend : {false, true}) {
                    PackRequest request;
                    request.count = 600;
                    request.arrangement = arrangement;
                    request.seed = seed;
                    request.sides = Sides::Periodic;
                    request.protocol.contact = contact;
                    if (blend) {
                        request.size_modes = {{1.0, 0.3}, {0.5, 0.7}};
                    }
                    const Pack pack = make_pack(request);
                    const double d = *pack.metadata.get_number("diameter");
                    const Periodic check = brute_force(pack, blend ? 0.5 * d : d);
                    BOOST_TEST(check.inside);
                    BOOST_TEST(check.min_gap_over_d >= -1e-12);
                    BOOST_TEST(check.across > 0U);
                    // check_pack's support count on the periodic cell grid (cells wrap).
                    Container cell;
                    cell.periodic = true;
                    const PackCheck grid_check =
                        check_pack(pack.particles, cell, 1e-12 * d, 1e-9 * (blend ? 0.5 * d : d));
                    BOOST_TEST(grid_check.unsupported == check.unsupported);
                    BOOST_TEST(grid_check.overlaps == 0U);
                    BOOST_TEST(pack.metadata.get("sides").value_or("") == "periodic");
                    BOOST_TEST(pack.metadata.get_number("fixed_wall").value_or(-1) == 0.0);
                    const Pack again = make_pack(request);
                    bool same = again.particles.size() == pack.particles.size();
                    for (std::size_t i = 0; same && i < pack.particles.size(); ++i) {
                        same = again.particles[i].center == pack.particles[i].center;
                    }
                    BOOST_TEST(same);
                }
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(relaxed_periodic_packs_are_certified_with_no_overlap) {
    for (const RelaxMode mode : {RelaxMode::Frictionless, RelaxMode::Frictional}) {
        for (const std::uint64_t seed : {1U, 2U}) {
            PackRequest request;
            // Frictional: 60 spheres at φ* 0.3 (d = 0.306 ≤ 1.25/4), a few seconds each.
            request.count = mode == RelaxMode::Frictionless ? 300 : 60;
            request.phi_target = mode == RelaxMode::Frictionless ? request.phi_target : 0.3;
            request.arrangement = Arrangement::LooseRandom;
            request.seed = seed;
            request.sides = Sides::Periodic;
            request.relax.mode = mode;
            request.relax.friction = 0.5;
            const Pack pack = make_pack(request);
            const double d = *pack.metadata.get_number("diameter");
            const Periodic check = brute_force(pack, d);
            BOOST_TEST(check.inside);
            BOOST_TEST(check.min_gap_over_d >= -1e-12);
            BOOST_TEST(check.across > 0U);
            BOOST_TEST(pack.metadata.get("certified").value_or("") == "true");
            BOOST_TEST(*pack.metadata.get_number("certificate_residual_max") <= 1e-3);
        }
    }
}

BOOST_AUTO_TEST_CASE(periodic_sides_refuse_what_they_cannot_do) {
    PackRequest request;
    request.arrangement = Arrangement::LooseRandom;
    request.sides = Sides::Periodic;
    request.count = 60;  // d = 0.39 > 1.25 / 4
    BOOST_CHECK_THROW(make_pack(request), ParameterError);
    PackRequest walls;
    walls.count = 300;
    BOOST_TEST(!make_pack(walls).metadata.contains("sides"));
}

BOOST_AUTO_TEST_SUITE(split_grids)

// A wide blend (1 : 0.25 : 0.15, r_max > 2 r_min) dropped with its small spheres in a grid
// of their own (Protocol's small_max_radius) and with one grid: the same centres, exactly,
// with walls and with periodic sides (the split changes where spheres are looked for,
// never which are found).
BOOST_AUTO_TEST_CASE(a_wide_blend_settles_the_same_with_split_grids) {
    for (const bool periodic : {false, true}) {
        PackRequest request;
        request.count = 10000;  // the fewest whose coarse spheres fit the periodic cell
        request.arrangement = Arrangement::LooseRandom;
        request.seed = 11;
        request.size_modes = {{1.0, 0.6}, {0.25, 0.2}, {0.15, 0.2}};
        request.fraction_basis = FractionBasis::Volume;
        request.sides = periodic ? Sides::Periodic : Sides::Walls;
        const Pack start = make_start_pack(request);
        Container container;
        container.periodic = periodic;
        const SizeClasses sizes = size_classes(start.particles);
        BOOST_TEST_REQUIRE(sizes.wide());
        const double r_max = sizes.max_radius;
        const double small_max = sizes.small_max_radius;
        BOOST_TEST_REQUIRE(small_max < 0.5 * r_max);
        std::vector<std::vector<Vec3>> centres(2);
        for (int split = 0; split < 2; ++split) {
            Protocol protocol(container, request.protocol, r_max, split == 1 ? small_max : 0.0);
            Random rng(request.seed);
            std::vector<Particle> particles = start.particles;
            for (Particle& p : particles) {
                p.center = container.wrapped(protocol.drop(p, rng).center);
                protocol.settle(p);
                centres[static_cast<std::size_t>(split)].push_back(p.center);
            }
            BOOST_TEST(protocol.settled_count() >= particles.size());
        }
        BOOST_TEST_REQUIRE(centres[0].size() == centres[1].size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < centres[0].size(); ++i) {
            differing += centres[0][i] == centres[1][i] ? 0 : 1;
        }
        BOOST_TEST(differing == 0u);
    }
}

BOOST_AUTO_TEST_SUITE_END()
