// The contact-dynamics settling (contact_dynamics.hpp): closed-form equilibria (a sphere on
// the floor, a column, a sphere on three held by the walls), its forces checked sphere by
// sphere against the weights here (brute force) and by the certificate (whose LP sees only
// the final positions), relaxed packs over seeds, the frictional settling on a tripod
// (certified by the frictional certificate's LP), and the refusal of bad options.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "sgmp/engine/contact_dynamics.hpp"
#include "sgmp/engine/equilibrium_certificate.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/pack/parameter_error.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

constexpr double kD = 0.1;

Particle sphere(double x, double y, double z) {
    return Particle{0, Vec3(x, y, z), 0.5 * kD, 0};
}

/// The force a settling's witness puts on the contact (first, second, partner), 0 if none.
double force_on(const ContactDynamicsStats& s, std::size_t first, std::size_t second,
                Partner partner) {
    for (const ContactForce& f : s.forces) {
        const bool same =
            f.partner == partner &&
            (partner != Partner::Sphere ? f.first == first
                                        : (f.first == first && f.second == second) ||
                                              (f.first == second && f.second == first));
        if (same) {
            return f.force;
        }
    }
    return 0.0;
}

/// The largest |Σ forces − weight| over the spheres, recomputed here from the witness and
/// the final positions (brute force, independent of the settling's own bookkeeping).
double largest_residual(const std::vector<Particle>& p, const Container& box, double d,
                        const std::vector<ContactForce>& forces) {
    std::vector<Vec3> net(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        net[i] = Vec3(0.0, -std::pow(2.0 * p[i].radius / d, 3), 0.0);
    }
    for (const ContactForce& f : forces) {
        if (f.partner == Partner::Sphere) {
            Vec3 n = p[f.second].center - p[f.first].center;
            double dx = n.x(), dz = n.z();
            box.to_nearest_image(dx, dz);
            n = Vec3(dx, n.y(), dz).normalized();
            net[f.first] -= f.force * n;
            net[f.second] += f.force * n;
            continue;
        }
        for (const WallGap& w : wall_gaps(p[f.first].center, p[f.first].radius, box)) {
            if (w.wall == f.partner) {
                net[f.first] += f.force * w.normal;
            }
        }
    }
    double largest = 0.0;
    for (const Vec3& r : net) {
        largest = std::max(largest, r.norm());
    }
    return largest;
}

/// Options converging the closed-form cases far below the default residual tolerance, with
/// each solver of the steps' contact problems: MPRGP with its SSOR preconditioner (the
/// default), MPRGP without, APGD and projected SOR.
std::vector<ContactDynamicsOptions> tight() {
    std::vector<ContactDynamicsOptions> all(4);
    all[1].ssor = 0.0;
    all[2].solver = ContactSolver::Apgd;
    all[3].solver = ContactSolver::Sor;
    for (ContactDynamicsOptions& o : all) {
        o.residual_tolerance = 1e-9;
        o.sweep_tolerance = 1e-13;
    }
    return all;
}

/// Three spheres on the floor of `box` at ρ = 0.7·d from the axis x = z = 0, at angles 0,
/// 120° and 240°, and a fourth 0.05·d above where it would rest on them (its centre
/// cos θ·d above theirs, cos θ = √(1 − ρ²/d²)).
std::vector<Particle> sphere_over_three(const Container& box) {
    const double rho = 0.7 * kD;
    const double y0 = box.floor + 0.5 * kD;
    std::vector<Particle> p;
    for (int k = 0; k < 3; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 3.0;
        p.push_back(sphere(rho * std::cos(a), y0, rho * std::sin(a)));
    }
    p.push_back(sphere(0, y0 + std::sqrt(1.0 - 0.49) * kD + 0.05 * kD, 0));
    return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(contact_dynamics)

BOOST_AUTO_TEST_CASE(a_sphere_falls_onto_the_floor_and_rests_on_its_weight) {
    const Container box;
    for (const ContactDynamicsOptions& o : tight()) {
        BOOST_TEST_CONTEXT("solver " << static_cast<int>(o.solver) << ", ssor " << o.ssor) {
            std::vector<Particle> p{sphere(0.1, box.floor + 0.6 * kD, -0.2)};
            const ContactDynamicsStats s = settle_by_contact_dynamics(p, box, kD, o);
            BOOST_TEST(s.converged);
            BOOST_TEST(std::abs(p[0].center.y() - (box.floor + 0.5 * kD)) <= 1e-9 * kD);
            BOOST_TEST(p[0].center.x() == 0.1);  // nothing pushes it sideways
            BOOST_TEST(s.forces.size() == 1u);
            BOOST_TEST(force_on(s, 0, 0, Partner::Floor) == 1.0,
                       boost::test_tools::tolerance(1e-6));
            BOOST_TEST(s.energy_drop == 0.1, boost::test_tools::tolerance(1e-6));
            const EquilibriumCertificate c = certify_frictionless(p, box, kD, {}, s.forces);
            BOOST_TEST(c.certified);
            BOOST_TEST(c.by_witness);
        }
    }
}

BOOST_AUTO_TEST_CASE(a_column_lands_and_carries_its_weights_down) {
    // Three spheres one above the other with gaps 0.3·d, 0.2·d, 0.1·d: they end touching,
    // the floor carries 3 weights, the pairs 2 and 1 (closed form).
    const Container box;
    const auto close = boost::test_tools::tolerance(1e-6);
    for (const ContactDynamicsOptions& o : tight()) {
        BOOST_TEST_CONTEXT("solver " << static_cast<int>(o.solver) << ", ssor " << o.ssor) {
            std::vector<Particle> p{sphere(0, box.floor + 0.8 * kD, 0),
                                    sphere(0, box.floor + 2.0 * kD, 0),
                                    sphere(0, box.floor + 3.1 * kD, 0)};
            const ContactDynamicsStats s = settle_by_contact_dynamics(p, box, kD, o);
            BOOST_TEST(s.converged);
            for (int k = 0; k < 3; ++k) {
                BOOST_TEST(std::abs(p[k].center.y() - (box.floor + (0.5 + k) * kD)) <= 1e-9 * kD);
            }
            BOOST_TEST(force_on(s, 0, 0, Partner::Floor) == 3.0, close);
            BOOST_TEST(force_on(s, 0, 1, Partner::Sphere) == 2.0, close);
            BOOST_TEST(force_on(s, 1, 2, Partner::Sphere) == 1.0, close);
            BOOST_TEST(s.energy_drop == 1.4, close);
            BOOST_TEST(largest_residual(p, box, kD, s.forces) <= 1e-6);
            BOOST_TEST(certify_frictionless(p, box, kD, {}, s.forces).by_witness);
        }
    }
}

BOOST_AUTO_TEST_CASE(a_sphere_on_three_held_by_the_walls_splits_its_weight) {
    // Three spheres on the floor at distance ρ = 0.7·d from the axis x = z = 0, at angles 0,
    // 120° and 240°, each against the walls that hold it outward (the box is cut to them),
    // apart from each other (their centres 0.7·√3·d > d apart); a fourth is dropped onto
    // them. With cos θ = √(1 − ρ²/d²) the contact normal's vertical part, each upper contact
    // carries 1/(3·cos θ), the floor 1 + 1/3 under each lower sphere, and the walls the
    // contacts' horizontal part ρ/(3·d·cos θ), split by the normals of the two walls at 120°
    // and 240°.
    const double rho = 0.7 * kD;
    const double r = 0.5 * kD;
    Container box;
    box.x_max = rho + r;
    box.x_min = -0.5 * rho - r;
    box.z_max = 0.5 * std::sqrt(3.0) * rho + r;
    box.z_min = -box.z_max;
    const double y0 = box.floor + r;
    const std::vector<Particle> p = sphere_over_three(box);
    const double cos_theta = std::sqrt(1.0 - 0.49);
    const double upper = 1.0 / (3.0 * cos_theta);
    const double push = upper * 0.7;
    const auto close = boost::test_tools::tolerance(1e-6);
    for (const ContactDynamicsOptions& o : tight()) {
        BOOST_TEST_CONTEXT("solver " << static_cast<int>(o.solver) << ", ssor " << o.ssor) {
            std::vector<Particle> q = p;
            const ContactDynamicsStats s = settle_by_contact_dynamics(q, box, kD, o);
            BOOST_TEST(s.converged);
            BOOST_TEST(std::abs(q[3].center.y() - (y0 + cos_theta * kD)) <= 1e-8 * kD);
            for (std::size_t k = 0; k < 3; ++k) {
                BOOST_TEST(force_on(s, k, 3, Partner::Sphere) == upper, close);
                BOOST_TEST(force_on(s, k, 0, Partner::Floor) == 4.0 / 3.0, close);
            }
            BOOST_TEST(force_on(s, 0, 0, Partner::XMax) == push, close);
            BOOST_TEST(force_on(s, 1, 0, Partner::XMin) == 0.5 * push, close);
            BOOST_TEST(force_on(s, 1, 0, Partner::ZMax) == 0.5 * std::sqrt(3.0) * push, close);
            BOOST_TEST(force_on(s, 2, 0, Partner::ZMin) == 0.5 * std::sqrt(3.0) * push, close);
            BOOST_TEST(largest_residual(q, box, kD, s.forces) <= 1e-5);
            const EquilibriumCertificate c = certify_frictionless(q, box, kD, {}, s.forces);
            BOOST_TEST(c.certified);
            BOOST_TEST(c.by_witness);
            BOOST_TEST(c.overlap_max_over_d <= 1e-9);
        }
    }
}

BOOST_AUTO_TEST_CASE(with_friction_a_sphere_rests_on_three_spread_on_the_floor) {
    // No walls: three spheres on the floor at ρ = 0.7·d from the axis, a fourth dropped onto
    // them. Frictionless they would slide apart; at μ = 1 floor and pair friction hold them
    // (the tripod of the frictional LP settling's test): the settling ends at rest with the
    // lower spheres on the floor, the upper one on them, and the frictional certificate
    // (its own LP on the final positions: force and torque, every force in the pyramid)
    // certifies it. A sphere on the floor alone carries its weight, and does not turn.
    const double r = 0.5 * kD;
    const Container box;
    const double y0 = box.floor + r;
    const std::vector<Particle> p = sphere_over_three(box);
    for (ContactDynamicsOptions o : tight()) {
        if (o.solver == ContactSolver::Apgd) {
            continue;  // friction: MPRGP over the pyramid's edges, or NSGS contact by contact
        }
        o.friction = 1.0;
        BOOST_TEST_CONTEXT("solver " << static_cast<int>(o.solver) << ", ssor " << o.ssor) {
            std::vector<Particle> q = p;
            const ContactDynamicsStats s = settle_by_contact_dynamics(q, box, kD, o);
            BOOST_TEST(s.converged);
            // The landing moves the lower spheres a little (MPRGP: the contacts dilate as
            // they slip) before friction holds them: they stay on the floor within 0.05·d of
            // where they were, and the upper sphere, lower than it started, rests on all
            // three.
            for (std::size_t k = 0; k < 3; ++k) {
                BOOST_TEST(std::abs(q[k].center.y() - y0) <= 1e-8 * kD, "sphere " << k);
                BOOST_TEST((q[k].center - p[k].center).norm() <= 0.05 * kD, "sphere " << k);
            }
            BOOST_TEST(q[3].center.y() < p[3].center.y());
            BOOST_TEST(s.forces.size() == 6u);  // three on the floor, three pairs
            const EquilibriumCertificate c = certify_frictional(q, box, kD, 1.0);
            BOOST_TEST(c.certified);
            BOOST_TEST(c.contacts == 6u);
            BOOST_TEST(c.residual_max <= 1e-6);
            std::vector<Particle> alone{sphere(0.1, box.floor + 0.6 * kD, -0.2)};
            const ContactDynamicsStats one = settle_by_contact_dynamics(alone, box, kD, o);
            BOOST_TEST(one.converged);
            BOOST_TEST(force_on(one, 0, 0, Partner::Floor) == 1.0,
                       boost::test_tools::tolerance(1e-6));
            BOOST_TEST(alone[0].center.x() == 0.1);
        }
    }
}

BOOST_AUTO_TEST_CASE(bad_options_are_refused) {
    std::vector<Particle> p{sphere(0, -0.5, 0)};
    const Container box;
    const auto refused = [&](auto change) {
        ContactDynamicsOptions o;
        change(o);
        BOOST_CHECK_THROW(settle_by_contact_dynamics(p, box, kD, o), std::invalid_argument);
    };
    refused([](ContactDynamicsOptions& o) { o.time_step = 0.0; });
    refused([](ContactDynamicsOptions& o) { o.time_step = NAN; });
    refused([](ContactDynamicsOptions& o) { o.residual_tolerance = -1.0; });
    refused([](ContactDynamicsOptions& o) { o.sweep_tolerance = INFINITY; });
    refused([](ContactDynamicsOptions& o) { o.relaxation = 2.0; });
    refused([](ContactDynamicsOptions& o) { o.step_shrink = 1.0; });
    refused([](ContactDynamicsOptions& o) { o.smallest_step = 0.0; });
    refused([](ContactDynamicsOptions& o) { o.max_steps = 0; });
    refused([](ContactDynamicsOptions& o) { o.max_sweeps = 0; });
    refused([](ContactDynamicsOptions& o) { o.ssor = 2.0; });
    refused([](ContactDynamicsOptions& o) { o.ssor = -0.5; });
    refused([](ContactDynamicsOptions& o) { o.ssor = NAN; });
    refused([](ContactDynamicsOptions& o) { o.friction = -0.1; });
    refused([](ContactDynamicsOptions& o) { o.friction = INFINITY; });
    refused([](ContactDynamicsOptions& o) { o.moving_sweep_tolerance = -1e-5; });
    refused([](ContactDynamicsOptions& o) { o.moving_sweep_tolerance = NAN; });
    refused([](ContactDynamicsOptions& o) {
        o.friction = 0.5;
        o.solver = ContactSolver::Apgd;
    });
    BOOST_CHECK_THROW(settle_by_contact_dynamics(p, box, 0.0), std::invalid_argument);
}

namespace {

/// A loose-random pack of 150 relaxed in `mode` and settled by the contact dynamics.
PackRequest dynamics_request(RelaxMode mode, std::uint64_t seed, Sides sides = Sides::Walls) {
    PackRequest request;
    request.count = 150;
    request.arrangement = Arrangement::LooseRandom;
    request.seed = seed;
    request.sides = sides;
    request.relax.mode = mode;
    request.relax.settle = RelaxSettle::Dynamics;
    return request;
}

}  // namespace

BOOST_AUTO_TEST_CASE(relaxed_packs_are_certified_by_the_settlings_own_forces) {
    // `--relax frictionless` ends with the contact dynamics; its forces certify the pack
    // (certificate_forces=settling-witness: no certificate LP), on walls and periodic sides.
    for (const Sides sides : {Sides::Walls, Sides::Periodic}) {
        for (const std::uint64_t seed : {1u, 2u, 3u}) {
            const Pack pack = make_pack(dynamics_request(RelaxMode::Frictionless, seed, sides));
            BOOST_TEST(*pack.metadata.get("certified") == "true", "seed " << seed);
            BOOST_TEST(*pack.metadata.get("certificate_forces") == "settling-witness",
                       "seed " << seed);
            BOOST_TEST(*pack.metadata.get_number("certificate_overlap_max") <= 1e-9);
        }
    }
}

BOOST_AUTO_TEST_CASE(a_frictional_pack_settled_by_nsgs_is_certified) {
    // `--relax frictional --relax-settle dynamics` at μ = 0.5: NSGS contact by contact in the
    // cone inside the certificate's pyramid; its last step's force vectors, written as the
    // pyramid's edge forces, balance force and torque on the final positions (the witness:
    // no certificate LP). Seed 1 of the eight measured
    // (sgmp/engine/notes/relax-frictional-dynamics-2026-12-07.md), all certified.
    const Pack pack = make_pack(dynamics_request(RelaxMode::Frictional, 1));
    BOOST_TEST(*pack.metadata.get("certified") == "true");
    BOOST_TEST(*pack.metadata.get("certificate") == "frictional");
    BOOST_TEST(*pack.metadata.get("certificate_forces") == "settling-witness");
    BOOST_TEST(*pack.metadata.get("relax_settle_end") == "residual");
    BOOST_TEST(*pack.metadata.get_number("certificate_residual_max") <= 1e-3);
    // The certificate's bound (its gap tolerance); the polish at h/3 leaves about 10⁻⁷·d.
    BOOST_TEST(*pack.metadata.get_number("certificate_overlap_max") <= 1e-6);
}

BOOST_AUTO_TEST_CASE(the_frictional_polish_goes_on_until_the_carrying_contacts_close) {
    // Seed 16 of the measured 24: at rest after the first polish step, a contact still carried
    // a force across a gap the certificate does not count (the witness then fails and the LP
    // leaves 0.119 m·g); the polish goes on at h/3 until every carrying contact is within
    // 0.5·10⁻⁶·d (2 steps more), and the witness certifies.
    const Pack pack = make_pack(dynamics_request(RelaxMode::Frictional, 16));
    BOOST_TEST(*pack.metadata.get("certified") == "true");
    BOOST_TEST(*pack.metadata.get("certificate_forces") == "settling-witness");
    BOOST_TEST(*pack.metadata.get("relax_settle_end") == "residual");
    // The rule was needed: this seed's polish took steps with a carrying contact open.
    BOOST_TEST(*pack.metadata.get_number("relax_settle_closing_steps") >= 1.0);
}

BOOST_AUTO_TEST_CASE(a_frictional_creep_the_polish_cannot_end_goes_back_to_the_first_step) {
    // Seed 46 of the main job's 48: its polish stalled at h/3 with 1.9·10⁻³ m·g left, above
    // the certificate's 10⁻³ (uncertified); back at the first step with inertia the creep
    // ends, and the witness certifies (633 steps, one of its two returns after a stall).
    const Pack pack = make_pack(dynamics_request(RelaxMode::Frictional, 46));
    BOOST_TEST(*pack.metadata.get("certified") == "true");
    BOOST_TEST(*pack.metadata.get_number("certificate_residual_max") <= 1e-3);
    // The rule was needed: the settling went back to its first step after a stall.
    BOOST_TEST(*pack.metadata.get_number("relax_settle_stall_returns") >= 1.0);
    BOOST_TEST(*pack.metadata.get_number("relax_settle_returns") >=
               *pack.metadata.get_number("relax_settle_stall_returns"));
}

BOOST_AUTO_TEST_CASE(the_same_request_settles_to_the_same_bytes) {
    const PackRequest request = dynamics_request(RelaxMode::Frictionless, 2);
    const Pack first = make_pack(request);
    const Pack second = make_pack(request);
    BOOST_TEST_REQUIRE(first.particles.size() == second.particles.size());
    for (std::size_t i = 0; i < first.particles.size(); ++i) {
        BOOST_TEST((first.particles[i].center == second.particles[i].center), "sphere " << i);
    }
    BOOST_TEST(*first.metadata.get("relax_settle_sweeps") ==
               *second.metadata.get("relax_settle_sweeps"));
}

BOOST_AUTO_TEST_CASE(the_settling_is_chosen_for_relaxations_only) {
    PackRequest request;
    request.count = 40;
    request.relax.mode = RelaxMode::None;
    request.relax.settle = RelaxSettle::Dynamics;
    BOOST_CHECK_THROW(validate(request), ParameterError);
    request.relax.mode = RelaxMode::Frictional;
    BOOST_CHECK_NO_THROW(validate(request));
    request.relax.mode = RelaxMode::Frictionless;
    BOOST_CHECK_NO_THROW(validate(request));
    // The LP settling, the default, is not recorded, so its packs keep their headers.
    request.relax.settle = RelaxSettle::Lp;
    BOOST_TEST(!make_pack(request).metadata.get("relax_settle").has_value());
    request.relax.settle = RelaxSettle::Dynamics;
    BOOST_TEST(*make_pack(request).metadata.get("relax_settle") == "dynamics");
}

BOOST_AUTO_TEST_SUITE_END()
