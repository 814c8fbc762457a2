#include "sgmp/engine/equilibrium_certificate.hpp"

#if SGMP_WITH_CLP
#include <ClpSimplex.hpp>
#include <CoinPackedMatrix.hpp>
#endif
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "sgmp/engine/coulomb_pyramid.hpp"
#include "sgmp/pack/cell_grid.hpp"
#include "sgmp/pack/pack_overlaps.hpp"
#include "sgmp/pack/periodic_images.hpp"

namespace sgmp::engine {
namespace {

/// One contact: the spheres it touches (second = none for a wall) and the unit normal
/// pushing `first` away from its partner.
struct Contact {
    std::size_t first = 0;
    std::size_t second = 0;
    bool wall = false;
    Vec3 normal = Vec3::Zero();
    Partner partner = Partner::Sphere;
};

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

std::vector<Contact> find_contacts(const std::vector<Particle>& particles, const Container& box,
                                   double tolerance, double& deepest) {
    std::vector<Contact> contacts;
    deepest = 0.0;
    const double r_max = max_radius(particles);
    if (particles.size() >= 2 && r_max > 0.0) {
        // With periodic sides, pairs with the images across the faces are the minimum-image
        // pairs (periodic_images.hpp): the pair (i, image of k) counts once, when i < k.
        const double reach = 2.0 * r_max + tolerance;
        const ImagedParticles imaged = with_periodic_images(particles, box, reach);
        const std::vector<Particle>& all = imaged.particles;
        const CellGrid grid(centers_of(all), reach);
        grid.for_each_pair_from(0, imaged.originals, [&](std::size_t i, std::size_t j, double r2) {
            const std::size_t k = imaged.source[j];
            if (j >= imaged.originals && !(i < k)) {
                return;
            }
            const double distance = std::sqrt(r2);
            const double gap = distance - all[i].radius - all[j].radius;
            if (gap <= tolerance && distance > 0.0) {
                deepest = std::max(deepest, -gap);
                contacts.push_back(
                    {i, k, false, (all[i].center - all[j].center) / distance, Partner::Sphere});
            }
        });
    }
    for (std::size_t i = 0; i < particles.size(); ++i) {
        for (const auto& [gap, normal, partner] :
             wall_gaps(particles[i].center, particles[i].radius, box)) {
            if (gap <= tolerance) {
                deepest = std::max(deepest, -gap);
                contacts.push_back({i, kNone, true, normal, partner});
            }
        }
    }
    return contacts;
}

/// The linear system A·f ≈ b of a certificate, column by column (compressed columns):
/// `rows` residual rows per sphere (3 forces, or 3 forces and 3 torques over d).
struct System {
    std::size_t rows = 3;
    std::vector<std::size_t> start{0};
    std::vector<std::uint32_t> row;
    std::vector<double> value;
    std::vector<double> b;

    void add(std::size_t sphere, std::size_t offset, const Vec3& v) {
        for (int a = 0; a < 3; ++a) {
            if (v[a] == 0.0) {
                continue;  // no explicit zeros: the LP solver may pivot on them
            }
            row.push_back(
                static_cast<std::uint32_t>(rows * sphere + offset + static_cast<std::size_t>(a)));
            value.push_back(v[a]);
        }
    }
    void close_column() { start.push_back(row.size()); }
    [[nodiscard]] std::size_t columns() const { return start.size() - 1; }
};

/// r = A·f − b.
std::vector<double> residuals(const System& s, const std::vector<double>& f) {
    std::vector<double> r(s.b.size());
    for (std::size_t i = 0; i < r.size(); ++i) {
        r[i] = -s.b[i];
    }
    for (std::size_t k = 0; k < s.columns(); ++k) {
        for (std::size_t e = s.start[k]; e < s.start[k + 1]; ++e) {
            r[s.row[e]] += s.value[e] * f[k];
        }
    }
    return r;
}

/// Per sphere, the Euclidean norm of its residual rows.
std::vector<double> per_sphere(const System& s, const std::vector<double>& r) {
    std::vector<double> norms(r.size() / s.rows, 0.0);
    for (std::size_t i = 0; i < r.size(); ++i) {
        norms[i / s.rows] += r[i] * r[i];
    }
    for (double& v : norms) {
        v = std::sqrt(v);
    }
    return norms;
}

/// The least-L1 residual forces: min Σ|A·f − b|₁ over f ≥ 0, as the LP
///     min Σ (pₖ + qₖ)  subject to  A·f + p − q = b,  f, p, q ≥ 0
/// by COIN-OR CLP's dual simplex (one thread, a fixed order: the same system gives the
/// same forces). Its optimum is 0 exactly when some f ≥ 0 balances every sphere; any f ≥ 0
/// it returns is a valid set of forces, so a small residual certifies.
std::vector<double> solve_forces(const System& system) {
#if !SGMP_WITH_CLP
    (void)system;
    throw std::runtime_error(
        "the equilibrium certificate needs COIN-OR CLP; this build has none (SGMP_WITH_CLP=OFF)");
#else
    const std::size_t m = system.b.size();
    const std::size_t k = system.columns();
    std::vector<CoinBigIndex> start(system.start.begin(), system.start.end());
    std::vector<int> row(system.row.begin(), system.row.end());
    std::vector<double> value = system.value;
    for (std::size_t i = 0; i < m; ++i) {  // p (+1) then q (−1) for residual row i
        for (const double sign : {1.0, -1.0}) {
            row.push_back(static_cast<int>(i));
            value.push_back(sign);
            start.push_back(static_cast<CoinBigIndex>(row.size()));
        }
    }
    const int columns = static_cast<int>(k + 2 * m);
    const CoinPackedMatrix matrix(true, static_cast<int>(m), columns,
                                  static_cast<CoinBigIndex>(value.size()), value.data(), row.data(),
                                  start.data(), nullptr);
    std::vector<double> lower(static_cast<std::size_t>(columns), 0.0);
    std::vector<double> upper(static_cast<std::size_t>(columns), COIN_DBL_MAX);
    std::vector<double> cost(static_cast<std::size_t>(columns), 1.0);
    std::fill(cost.begin(), cost.begin() + static_cast<std::ptrdiff_t>(k), 0.0);
    ClpSimplex model;
    model.setLogLevel(0);
    model.loadProblem(matrix, lower.data(), upper.data(), cost.data(), system.b.data(),
                      system.b.data());
    model.scaling(0);  // CLP's scaling leaves this LP's unscaled optimum infeasible
    model.setPrimalTolerance(1e-10);
    model.dual();
    if (model.status() == 0 && model.secondaryStatus() != 0) {
        model.primal(1);  // clean up on the unscaled problem
    }
    if (model.status() != 0 || model.secondaryStatus() != 0) {
        throw std::runtime_error("equilibrium certificate: the force LP failed (CLP status " +
                                 std::to_string(model.status()) + ", " +
                                 std::to_string(model.secondaryStatus()) + ")");
    }
    const double* x = model.primalColumnSolution();
    std::vector<double> f(x, x + k);
    for (double& v : f) {
        v = std::max(v, 0.0);  // within the LP's tolerance of its bound
    }
    return f;
#endif
}

/// A witness force on one contact: normal, and tangential on the contact key's lower
/// sphere (walls: on the sphere).
struct KeyedForce {
    double normal = 0.0;
    Vec3 tangential = Vec3::Zero();
};

/// The witness's forces on `contacts` (0 where it names none), as one column per contact
/// (frictionless) or the pyramid's 8 edge multipliers per contact (frictional,
/// coulomb_pyramid.hpp); throws on a negative force.
std::vector<double> witness_forces(const std::vector<Contact>& contacts,
                                   std::span<const ContactForce> witness,
                                   std::optional<double> friction) {
    std::unordered_map<std::uint64_t, KeyedForce> by_key;
    by_key.reserve(witness.size());
    for (const ContactForce& w : witness) {
        if (!(w.force >= 0.0)) {
            throw std::invalid_argument("certificate: a witness force is negative or NaN");
        }
        KeyedForce& k = by_key[contact_key(w.first, w.second, w.partner)];
        k.normal += w.force;
        const bool on_lower = w.partner != Partner::Sphere || w.first < w.second;
        k.tangential += on_lower ? w.tangential : Vec3(-w.tangential);
    }
    const std::size_t per = friction ? static_cast<std::size_t>(kPyramidEdges) : 1;
    std::vector<double> f(per * contacts.size(), 0.0);
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const Contact& c = contacts[k];
        const auto it = by_key.find(contact_key(c.first, c.second, c.partner));
        if (it == by_key.end()) {
            continue;
        }
        if (!friction) {
            f[k] = it->second.normal;
            continue;
        }
        const bool first_is_lower = c.wall || c.first < c.second;
        const Vec3 t = first_is_lower ? it->second.tangential : Vec3(-it->second.tangential);
        const auto beta = pyramid_edge_forces(c.normal, *friction, it->second.normal, t);
        std::copy(beta.begin(), beta.end(), f.begin() + static_cast<std::ptrdiff_t>(per * k));
    }
    return f;
}

/// The certificate's system: one column per contact (frictionless), or per edge of an
/// inscribed pyramid of the Coulomb cone (frictional, with torques over d).
System build_system(const std::vector<Particle>& particles, const std::vector<Contact>& contacts,
                    const std::vector<double>& weight, double diameter,
                    std::optional<double> friction) {
    System s;
    s.rows = friction ? 6 : 3;
    s.b.assign(s.rows * particles.size(), 0.0);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        s.b[s.rows * i + 1] = weight[i];
    }
    for (const Contact& c : contacts) {
        if (!friction) {
            s.add(c.first, 0, c.normal);
            if (!c.wall) {
                s.add(c.second, 0, -c.normal);
            }
            s.close_column();
            continue;
        }
        for (const Vec3& edge : coulomb_pyramid(c.normal, *friction)) {
            const Vec3 moment = c.normal.cross(edge);  // torque per unit lever (−r n) × edge
            s.add(c.first, 0, edge);
            s.add(c.first, 3, -particles[c.first].radius / diameter * moment);
            if (!c.wall) {
                s.add(c.second, 0, -edge);
                s.add(c.second, 3, -particles[c.second].radius / diameter * moment);
            }
            s.close_column();
        }
    }
    return s;
}

/// Per-sphere residuals of forces `f` into `cert`.
void record_residuals(const System& system, const std::vector<double>& f,
                      EquilibriumCertificate& cert) {
    const auto r = residuals(system, f);
    cert.residual = per_sphere(system, r);
    cert.residual_sum = 0.0;
    cert.residual_max = 0.0;
    cert.worst_sphere = 0;
    for (std::size_t i = 0; i < cert.residual.size(); ++i) {
        for (std::size_t a = 0; a < system.rows; ++a) {
            cert.residual_sum += std::abs(r[system.rows * i + a]);
        }
        if (cert.residual[i] > cert.residual_max) {
            cert.residual_max = cert.residual[i];
            cert.worst_sphere = i;
        }
    }
}

EquilibriumCertificate certify(const std::vector<Particle>& particles, const Container& container,
                               double diameter, std::optional<double> friction,
                               const CertificateOptions& options,
                               std::span<const ContactForce> witness) {
    if (!(diameter > 0.0) || !(options.gap_tolerance_over_d >= 0.0) ||
        !(options.residual_tolerance > 0.0) || (friction && !(*friction >= 0.0))) {
        throw std::invalid_argument(
            "certificate needs a diameter > 0, a gap tolerance >= 0, a residual tolerance > 0 "
            "and a friction >= 0");
    }
    EquilibriumCertificate cert;
    const std::size_t n = particles.size();
    double deepest = 0.0;
    const auto contacts =
        find_contacts(particles, container, options.gap_tolerance_over_d * diameter, deepest);
    cert.contacts = contacts.size();
    cert.overlap_max_over_d = deepest / diameter;
    const double d3 = diameter * diameter * diameter;
    std::vector<double> weight(n);
    std::vector<int> degree(n, 0);
    for (const Contact& c : contacts) {
        ++degree[c.first];
        degree[c.second == kNone ? c.first : c.second] += c.wall ? 0 : 1;
    }
    const int enough = friction ? 1 : 3;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = particles[i].radius;
        weight[i] = 8.0 * r * r * r / d3;
        cert.weight_sum += weight[i];
        cert.underconstrained += degree[i] < enough ? 1 : 0;
    }
    const System system = build_system(particles, contacts, weight, diameter, friction);
    const bool fits = cert.overlap_max_over_d <= options.gap_tolerance_over_d;
    std::vector<double> f;
    if (!witness.empty()) {
        f = witness_forces(contacts, witness, friction);
        record_residuals(system, f, cert);
        cert.by_witness = fits && cert.residual_max <= options.residual_tolerance;
    }
    if (!cert.by_witness) {
        f = solve_forces(system);
        record_residuals(system, f, cert);
    }
    // Per contact, the total force (the sum over its pyramid's edges, for friction).
    const std::size_t per = friction ? static_cast<std::size_t>(kPyramidEdges) : 1;
    cert.force.assign(contacts.size(), 0.0);
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        for (std::size_t e = 0; e < per; ++e) {
            cert.force[k] += f[per * k + e];  // the normal part: each edge has n·edge = 1
        }
    }
    cert.certified = fits && cert.residual_max <= options.residual_tolerance;
    return cert;
}

}  // namespace

std::uint64_t contact_key(std::size_t first, std::size_t second, Partner partner) {
    if (partner != Partner::Sphere) {
        second = static_cast<std::size_t>(partner);  // walls: small partners, sphere first
        return (static_cast<std::uint64_t>(first) << 32) | (0xFFFFFFF0U + second);
    }
    const auto [lo, hi] = std::minmax(first, second);
    return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

std::array<WallGap, 5> wall_gaps(const Vec3& c, double r, const Container& box) {
    if (box.periodic) {  // no walls: the lateral gaps never close
        return {{
            {c.y() - r - box.floor, Vec3(0.0, 1.0, 0.0), Partner::Floor},
            {INFINITY, Vec3(1.0, 0.0, 0.0), Partner::XMin},
            {INFINITY, Vec3(-1.0, 0.0, 0.0), Partner::XMax},
            {INFINITY, Vec3(0.0, 0.0, 1.0), Partner::ZMin},
            {INFINITY, Vec3(0.0, 0.0, -1.0), Partner::ZMax},
        }};
    }
    return {{
        {c.y() - r - box.floor, Vec3(0.0, 1.0, 0.0), Partner::Floor},
        {c.x() - r - box.x_min, Vec3(1.0, 0.0, 0.0), Partner::XMin},
        {box.x_max - c.x() - r, Vec3(-1.0, 0.0, 0.0), Partner::XMax},
        {c.z() - r - box.z_min, Vec3(0.0, 0.0, 1.0), Partner::ZMin},
        {box.z_max - c.z() - r, Vec3(0.0, 0.0, -1.0), Partner::ZMax},
    }};
}

EquilibriumCertificate certify_frictionless(const std::vector<Particle>& particles,
                                            const Container& container, double diameter,
                                            const CertificateOptions& options,
                                            std::span<const ContactForce> witness) {
    return certify(particles, container, diameter, std::nullopt, options, witness);
}

EquilibriumCertificate certify_frictional(const std::vector<Particle>& particles,
                                          const Container& container, double diameter,
                                          double friction, const CertificateOptions& options,
                                          std::span<const ContactForce> witness) {
    return certify(particles, container, diameter, friction, options, witness);
}

}  // namespace sgmp::engine
