#include "sgmp/engine/hard_sphere_settle.hpp"

#include <ClpSimplex.hpp>
#include <CoinPackedMatrix.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <unordered_map>

#include "sgmp/engine/neighbour_list.hpp"

namespace sgmp::engine {
namespace {

/// Largest violation of a bound or a row (in units of s) accepted from the LP: its step
/// then overlaps by at most 10⁻⁸·s.
constexpr double kFeasibility = 1e-8;
/// Share of the spheres moving the full trust region vertically that grows it.
constexpr double kSlidingShare = 0.02;
/// The trust region shrinks when a step lowers the energy by less than this times s (in
/// m·g): the energy's slope along the best feasible step, which vanishes at an equilibrium.
constexpr double kStallRate = 1e-4;

std::uint64_t pair_key(std::uint32_t i, std::uint32_t j) {
    return (static_cast<std::uint64_t>(i) << 32) | j;
}

/// The LP of one iteration in the scaled variables u = Δ/s (units of d), and the pairs of
/// its rows.
struct Step {
    std::vector<int> row_index;
    std::vector<int> col_index;
    std::vector<double> element;
    std::vector<double> row_upper;
    std::vector<std::uint64_t> row_pair;
    std::vector<double> col_lower;
    std::vector<double> col_upper;
    std::vector<double> objective;
};

/// Columns of sphere i: its scaled moves along x, y and z.
constexpr std::size_t kColumns = 3;

Step build_step(const std::vector<Ball>& balls, const NeighbourList& list, const Container& box,
                double trust, const std::vector<double>& weight) {
    Step st;
    const std::size_t n = balls.size();
    const double cutoff = 2.0 * std::sqrt(3.0) * trust;
    int row = 0;
    for (std::size_t i = 0; i < n; ++i) {
        for (const std::uint32_t j : list.of(i)) {
            const double dx = balls[j].x - balls[i].x;
            const double dy = balls[j].y - balls[i].y;
            const double dz = balls[j].z - balls[i].z;
            const double dist = std::sqrt(dx * dx + dy * dy + dz * dz);
            const double gap = dist - balls[i].r - balls[j].r;
            if (gap >= cutoff || dist == 0.0) {
                continue;
            }
            const double normal[3] = {dx / dist, dy / dist, dz / dist};
            for (std::size_t a = 0; a < 3; ++a) {
                if (normal[a] == 0.0) {
                    continue;  // no explicit zeros: CLP may pivot on them
                }
                for (const auto& [sphere, sign] :
                     {std::pair{i, 1.0}, std::pair{std::size_t{j}, -1.0}}) {
                    st.row_index.push_back(row);
                    st.col_index.push_back(static_cast<int>(kColumns * sphere + a));
                    st.element.push_back(sign * normal[a]);
                }
            }
            st.row_upper.push_back(gap / trust);
            st.row_pair.push_back(pair_key(static_cast<std::uint32_t>(i), j));
            ++row;
        }
    }
    st.col_lower.assign(kColumns * n, -1.0);
    st.col_upper.assign(kColumns * n, 1.0);
    st.objective.assign(kColumns * n, 0.0);
    const auto clamp = [&](std::size_t col, double lo, double hi) {
        st.col_upper[col] = std::min(1.0, hi / trust);
        st.col_lower[col] = std::min(std::max(-1.0, lo / trust), st.col_upper[col]);  // rounding
    };
    for (std::size_t i = 0; i < n; ++i) {
        const Ball& b = balls[i];
        const std::size_t c = kColumns * i;
        clamp(c, box.x_min + b.r - b.x, box.x_max - b.r - b.x);
        clamp(c + 1, box.floor + b.r - b.y, 1e300);
        clamp(c + 2, box.z_min + b.r - b.z, box.z_max - b.r - b.z);
        st.objective[c + 1] = weight[i];
    }
    return st;
}

/// Sphere i's scaled displacement from the LP's columns.
std::array<double, 3> displacement(const std::vector<double>& u, std::size_t i) {
    const std::size_t c = kColumns * i;
    return {u[c], u[c + 1], u[c + 2]};
}

/// The basis of the last LP, to warm-start the next.
struct Basis {
    std::vector<ClpSimplex::Status> columns;
    std::unordered_map<std::uint64_t, ClpSimplex::Status> rows;
};

/// Largest violation of the step's bounds and rows by the LP's solution.
double violation(const ClpSimplex& model, const Step& st) {
    const double* u = model.primalColumnSolution();
    double worst = 0.0;
    for (std::size_t k = 0; k < st.objective.size(); ++k) {
        worst = std::max({worst, st.col_lower[k] - u[k], u[k] - st.col_upper[k]});
    }
    std::vector<double> activity(st.row_upper.size(), 0.0);
    for (std::size_t e = 0; e < st.element.size(); ++e) {
        activity[static_cast<std::size_t>(st.row_index[e])] +=
            st.element[e] * u[static_cast<std::size_t>(st.col_index[e])];
    }
    for (std::size_t r = 0; r < activity.size(); ++r) {
        worst = std::max(worst, activity[r] - st.row_upper[r]);
    }
    return std::isfinite(worst) ? worst : INFINITY;
}

/// How an LP starts: from the last basis, from Δ = 0 by the primal simplex, or from the
/// slack basis by the dual simplex (the last resort).
enum class Start { Warm, ValuesPass, Slack };

/// Solves the step's LP with CLP from `start`, falling back to the next start when CLP
/// cannot use it.
void solve_step(ClpSimplex& model, const Step& st, const Basis& basis, Start start,
                SettleStats& stats) {
    const bool warm = start == Start::Warm && basis.columns.size() == st.objective.size();
    CoinPackedMatrix matrix(false, st.row_index.data(), st.col_index.data(), st.element.data(),
                            static_cast<CoinBigIndex>(st.element.size()));
    // The triplets give the dimensions by their largest indices: spheres with no rows, last
    // in the order, would be left out.
    matrix.setDimensions(static_cast<int>(st.row_upper.size()),
                         static_cast<int>(st.objective.size()));
    const std::vector<double> row_lower(st.row_upper.size(), -COIN_DBL_MAX);
    model.loadProblem(matrix, st.col_lower.data(), st.col_upper.data(), st.objective.data(),
                      row_lower.data(), st.row_upper.data());
    if (warm) {
        for (std::size_t k = 0; k < basis.columns.size(); ++k) {
            model.setColumnStatus(static_cast<int>(k), basis.columns[k]);
        }
        for (std::size_t r = 0; r < st.row_pair.size(); ++r) {
            const auto it = basis.rows.find(st.row_pair[r]);
            model.setRowStatus(static_cast<int>(r),
                               it != basis.rows.end() ? it->second : ClpSimplex::basic);
        }
    }
    model.scaling(0);  // the rows are unit normals, the bounds ±1: scaled already
    model.setPrimalTolerance(1e-10);
    model.setDualTolerance(1e-10);
    const auto t0 = std::chrono::steady_clock::now();
    if (warm || start == Start::Slack) {
        model.dual();
    } else {
        // No basis to start from (the first LP): the primal simplex from the feasible point
        // Δ = 0 (CLP's values pass) takes about 3,400 pivots at N = 1002, where the dual
        // simplex from the slack basis took 10,800–86,800 (docs/relax-certified.md).
        double* u = model.primalColumnSolution();
        for (std::size_t k = 0; k < st.objective.size(); ++k) {
            u[k] = std::clamp(0.0, st.col_lower[k], st.col_upper[k]);
        }
        model.primal(1);
    }
    stats.lp_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    stats.lp_pivots += model.numberIterations();
    if (model.status() != 0 || model.secondaryStatus() != 0 ||
        violation(model, st) > kFeasibility) {
        if (start != Start::Slack) {  // a start CLP could not use: solve afresh
            ClpSimplex fresh;
            fresh.setLogLevel(0);
            solve_step(fresh, st, basis, warm ? Start::ValuesPass : Start::Slack, stats);
            model = fresh;
            return;
        }
        throw std::runtime_error("settle_hard_spheres: the LP of iteration " +
                                 std::to_string(stats.iterations) + " failed (CLP status " +
                                 std::to_string(model.status()) + ", " +
                                 std::to_string(model.secondaryStatus()) + ", violation " +
                                 std::to_string(violation(model, st)) + ")");
    }
}

void save_basis(const ClpSimplex& model, const Step& st, Basis& basis) {
    basis.columns.resize(st.objective.size());
    for (std::size_t k = 0; k < basis.columns.size(); ++k) {
        basis.columns[k] = model.getColumnStatus(static_cast<int>(k));
    }
    basis.rows.clear();
    for (std::size_t r = 0; r < st.row_pair.size(); ++r) {
        basis.rows.emplace(st.row_pair[r], model.getRowStatus(static_cast<int>(r)));
    }
}

/// The contact forces of the step's LP optimum (see the header): pair rows' −y, and the
/// reduced costs of columns held by a wall or the floor.
std::vector<ContactForce> lp_forces(const ClpSimplex& model, const Step& st) {
    std::vector<ContactForce> forces;
    const double* y = model.dualRowSolution();
    for (std::size_t r = 0; r < st.row_pair.size(); ++r) {
        if (-y[r] > 0.0) {
            forces.push_back({static_cast<std::size_t>(st.row_pair[r] >> 32),
                              static_cast<std::size_t>(st.row_pair[r] & 0xFFFFFFFFU),
                              Partner::Sphere, -y[r]});
        }
    }
    const double* z = model.getReducedCost();
    constexpr std::array<std::pair<Partner, Partner>, kColumns> walls{
        {{Partner::XMin, Partner::XMax},
         {Partner::Floor, Partner::Floor},
         {Partner::ZMin, Partner::ZMax}}};
    for (std::size_t col = 0; col < st.objective.size(); ++col) {
        const auto [low, high] = walls[col % kColumns];
        const std::size_t sphere = col / kColumns;
        if (z[col] > 0.0 && st.col_lower[col] > -1.0) {  // held from below by a wall
            forces.push_back({sphere, 0, low, z[col]});
        } else if (z[col] < 0.0 && st.col_upper[col] < 1.0 && col % kColumns != 1) {
            forces.push_back({sphere, 0, high, -z[col]});
        }
    }
    return forces;
}

}  // namespace

SettleStats settle_hard_spheres(std::vector<Particle>& particles, const Container& container,
                                double diameter, const SettleOptions& options) {
    if (!(diameter > 0.0) || !(options.trust_min > 0.0) ||
        !(options.trust_start >= options.trust_min) ||
        !(options.trust_max >= options.trust_start)) {
        throw std::invalid_argument("settle_hard_spheres: bad diameter or trust region");
    }
    SettleStats stats;
    const std::size_t n = particles.size();
    if (n == 0) {
        return stats;
    }
    // Everything in units of d.
    std::vector<Ball> balls(n);
    std::vector<double> weight(n);
    const Container box{container.x_min / diameter, container.x_max / diameter,
                        container.z_min / diameter, container.z_max / diameter,
                        container.floor / diameter};
    for (std::size_t i = 0; i < n; ++i) {
        const Particle& p = particles[i];
        balls[i] = {p.center.x() / diameter, p.center.y() / diameter, p.center.z() / diameter,
                    p.radius / diameter};
        weight[i] = std::pow(2.0 * balls[i].r, 3);
    }
    const std::vector<Ball> start = balls;
    double trust = options.trust_start;
    NeighbourList list;
    Basis basis;
    ClpSimplex model;
    model.setLogLevel(0);
    while (stats.iterations < options.max_iterations) {
        list.build(balls, 2.0 * std::sqrt(3.0) * trust);
        const Step st = build_step(balls, list, box, trust, weight);
        std::vector<double> u(kColumns * n);
        if (st.row_pair.empty()) {  // no pair can meet: each sphere falls as far as it may
            for (std::size_t i = 0; i < n; ++i) {
                u[kColumns * i + 1] = st.col_lower[kColumns * i + 1];
            }
            basis.columns.clear();
            stats.forces.clear();  // a sphere resting on the floor carries its weight there
            for (std::size_t i = 0; i < n; ++i) {
                if (st.col_lower[kColumns * i + 1] > -1.0) {
                    stats.forces.push_back({i, 0, Partner::Floor, weight[i]});
                }
            }
        } else {
            solve_step(model, st, basis, Start::Warm, stats);
            std::copy_n(model.primalColumnSolution(), kColumns * n, u.begin());
            save_basis(model, st, basis);
            stats.forces = lp_forces(model, st);
        }
        ++stats.iterations;
        double drop = 0.0;
        std::size_t falling = 0;  // spheres held by the trust region on their way down
        for (std::size_t i = 0; i < n; ++i) {
            const auto [ux, uy, uz] = displacement(u, i);
            balls[i].x += trust * ux;
            balls[i].y += trust * uy;
            balls[i].z += trust * uz;
            drop -= weight[i] * trust * uy;
            falling += uy <= -1.0 + 1e-6 ? 1 : 0;
        }
        stats.energy_drop += drop;
        if (static_cast<double>(falling) > kSlidingShare * static_cast<double>(n)) {
            trust = std::min(2.0 * trust, options.trust_max);
        } else if (drop < kStallRate * trust) {
            trust /= 4.0;
        }
        if (options.progress) {
            options.progress(stats.iterations, trust);
        }
        if (trust < options.trust_min) {
            stats.converged = true;
            break;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        const double dx = balls[i].x - start[i].x;
        const double dy = balls[i].y - start[i].y;
        const double dz = balls[i].z - start[i].z;
        stats.move_max = std::max(stats.move_max, std::sqrt(dx * dx + dy * dy + dz * dz));
        particles[i].center =
            Vec3(balls[i].x * diameter, balls[i].y * diameter, balls[i].z * diameter);
    }
    return stats;
}

}  // namespace sgmp::engine
