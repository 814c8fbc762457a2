#include "sgmp/engine/equilibrium_certificate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sgmp/pack/cell_grid.hpp"
#include "sgmp/pack/pack_overlaps.hpp"

namespace sgmp::engine {
namespace {

/// One contact: the spheres it touches (second = none for a wall) and the unit normal
/// pushing `first` away from its partner.
struct Contact {
    std::size_t first = 0;
    std::size_t second = 0;
    bool wall = false;
    Vec3 normal = Vec3::Zero();
};

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

std::vector<Contact> find_contacts(const std::vector<Particle>& particles, const Container& box,
                                   double tolerance, double& deepest) {
    std::vector<Contact> contacts;
    deepest = 0.0;
    const double r_max = max_radius(particles);
    if (particles.size() >= 2 && r_max > 0.0) {
        const CellGrid grid(centers_of(particles), 2.0 * r_max + tolerance);
        grid.for_each_pair([&](std::size_t i, std::size_t j, double r2) {
            const double distance = std::sqrt(r2);
            const double gap = distance - particles[i].radius - particles[j].radius;
            if (gap <= tolerance && distance > 0.0) {
                deepest = std::max(deepest, -gap);
                contacts.push_back(
                    {i, j, false, (particles[i].center - particles[j].center) / distance});
            }
        });
    }
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Vec3& c = particles[i].center;
        const double r = particles[i].radius;
        const std::array<std::pair<double, Vec3>, 5> walls{{
            {c.y() - r - box.floor, Vec3(0.0, 1.0, 0.0)},
            {c.x() - r - box.x_min, Vec3(1.0, 0.0, 0.0)},
            {box.x_max - c.x() - r, Vec3(-1.0, 0.0, 0.0)},
            {c.z() - r - box.z_min, Vec3(0.0, 0.0, 1.0)},
            {box.z_max - c.z() - r, Vec3(0.0, 0.0, -1.0)},
        }};
        for (const auto& [gap, normal] : walls) {
            if (gap <= tolerance) {
                deepest = std::max(deepest, -gap);
                contacts.push_back({i, kNone, true, normal});
            }
        }
    }
    return contacts;
}

/// Rᵢ = Σ_c f_c·nᵢ,c − wᵢ·ŷ for every sphere.
std::vector<Vec3> residuals(const std::vector<Contact>& contacts, const std::vector<double>& weight,
                            const std::vector<double>& force) {
    std::vector<Vec3> r(weight.size());
    for (std::size_t i = 0; i < weight.size(); ++i) {
        r[i] = Vec3(0.0, -weight[i], 0.0);
    }
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const Contact& c = contacts[k];
        r[c.first] += force[k] * c.normal;
        if (!c.wall) {
            r[c.second] -= force[k] * c.normal;
        }
    }
    return r;
}

/// ½·Σ|Rᵢ|² and its gradient with respect to each f_c.
double objective(const std::vector<Contact>& contacts, const std::vector<Vec3>& r,
                 std::vector<double>& gradient) {
    double sum = 0.0;
    for (const Vec3& v : r) {
        sum += v.squaredNorm();
    }
    gradient.resize(contacts.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const Contact& c = contacts[k];
        gradient[k] = c.normal.dot(c.wall ? r[c.first] : Vec3(r[c.first] - r[c.second]));
    }
    return 0.5 * sum;
}

double largest(const std::vector<Vec3>& r) {
    double m = 0.0;
    for (const Vec3& v : r) {
        m = std::max(m, v.norm());
    }
    return m;
}

/// Non-negative least squares min ½·Σ|Rᵢ(f)|², f ≥ 0, by the spectral projected gradient
/// (Birgin, Martínez & Raydan, SIAM J. Optim. 10, 1196, 2000): Barzilai–Borwein steps,
/// projected on f ≥ 0, with a non-monotone line search over the last 10 values. Stops
/// when every |Rᵢ| ≤ `target`, when 500 iterations lower the objective by less than 10⁻⁴
/// of itself, or after kMaxIterations; any f ≥ 0 it returns is a valid set of forces, so
/// a small residual certifies, whatever the stopping reason.
std::vector<double> solve_forces(const std::vector<Contact>& contacts,
                                 const std::vector<double>& weight, double target) {
    constexpr int kMaxIterations = 200000;
    constexpr int kMemory = 10;
    constexpr int kCheckEvery = 500;  // stop when 500 iterations gain less than kStall
    constexpr double kStall = 1e-4;
    std::vector<double> f(contacts.size(), 0.0);
    std::vector<double> g;
    auto r = residuals(contacts, weight, f);
    double value = objective(contacts, r, g);
    std::vector<double> history(kMemory, value);
    double step = 0.5;  // 1 / the largest column norm² (a pair's column has norm² 2)
    std::vector<double> trial(f.size());
    std::vector<double> g_trial;
    double checkpoint = value;
    for (int it = 0; it < kMaxIterations && largest(r) > target; ++it) {
        if (it % kCheckEvery == kCheckEvery - 1) {
            if (checkpoint - value <= kStall * checkpoint) {
                break;  // the least-squares optimum, to the solver's precision
            }
            checkpoint = value;
        }
        const double reference = *std::max_element(history.begin(), history.end());
        double lambda = 1.0;
        std::vector<Vec3> r_trial;
        double value_trial = 0.0;
        double descent = 0.0;
        for (int tries = 0; tries < 40; ++tries) {
            descent = 0.0;
            for (std::size_t k = 0; k < f.size(); ++k) {
                const double projected = std::max(0.0, f[k] - step * g[k]);
                trial[k] = f[k] + lambda * (projected - f[k]);
                descent += g[k] * (trial[k] - f[k]);
            }
            r_trial = residuals(contacts, weight, trial);
            value_trial = objective(contacts, r_trial, g_trial);
            if (value_trial <= reference + 1e-4 * descent) {
                break;
            }
            lambda *= 0.5;
        }
        double ss = 0.0;
        double sy = 0.0;
        for (std::size_t k = 0; k < f.size(); ++k) {
            const double sk = trial[k] - f[k];
            ss += sk * sk;
            sy += sk * (g_trial[k] - g[k]);
        }
        if (ss == 0.0) {
            break;  // a fixed point of the projection: the least-squares optimum
        }
        step = sy > 0.0 ? std::clamp(ss / sy, 1e-10, 1e10) : 1e10;
        f.swap(trial);
        g.swap(g_trial);
        r.swap(r_trial);
        value = value_trial;
        history[static_cast<std::size_t>(it % kMemory)] = value;
    }
    return f;
}

}  // namespace

EquilibriumCertificate certify_frictionless(const std::vector<Particle>& particles,
                                            const Container& container, double diameter,
                                            const CertificateOptions& options) {
    if (!(diameter > 0.0) || !(options.gap_tolerance_over_d >= 0.0) ||
        !(options.residual_tolerance > 0.0)) {
        throw std::invalid_argument(
            "certificate needs a diameter > 0, a gap tolerance >= 0 and "
            "a residual tolerance > 0");
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
    for (std::size_t i = 0; i < n; ++i) {
        const double r = particles[i].radius;
        weight[i] = 8.0 * r * r * r / d3;
        cert.weight_sum += weight[i];
        cert.underconstrained += degree[i] < 3 ? 1 : 0;
    }
    cert.force = solve_forces(contacts, weight, 0.1 * options.residual_tolerance);
    const auto residual = residuals(contacts, weight, cert.force);
    cert.residual.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        cert.residual[i] = residual[i].norm();
        cert.residual_sum += residual[i].lpNorm<1>();
        if (cert.residual[i] > cert.residual_max) {
            cert.residual_max = cert.residual[i];
            cert.worst_sphere = i;
        }
    }
    cert.certified = cert.overlap_max_over_d <= options.gap_tolerance_over_d &&
                     cert.residual_max <= options.residual_tolerance;
    return cert;
}

}  // namespace sgmp::engine
