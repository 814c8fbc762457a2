#include "sgmp/engine/hard_sphere_settle.hpp"

#include <ClpSimplex.hpp>
#include <CoinPackedMatrix.hpp>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <unordered_map>

#include "hard_sphere_settle_step.hpp"
#include "sgmp/engine/coulomb_pyramid.hpp"
#include "sgmp/engine/neighbour_list.hpp"

namespace sgmp::engine {
namespace {

using namespace settle_step;

/// Largest violation of a bound or a row (in units of s) accepted from the LP: its step
/// then overlaps by at most 10⁻⁸·s.
constexpr double kFeasibility = 1e-8;
/// Share of the spheres moving the full trust region vertically that grows it.
constexpr double kSlidingShare = 0.02;
/// The trust region shrinks when a step lowers the energy by less than this times s (in
/// m·g): the energy's slope along the best feasible step, which vanishes at an equilibrium.
constexpr double kStallRate = 1e-4;
/// Steps in a row that neither grow nor shrink the trust region after which it is doubled:
/// a few spheres creeping down a shallow slope (or a slide held by friction's rows) lower
/// the energy at a steady rate per s without a collective fall, and at a small s took the
/// whole iteration budget (frictional N = 60, seeds 3, 5, 8: 5,000 LPs at s = 10⁻⁹–10⁻⁶·d).
constexpr int kSteadySteps = 8;
/// Frictional: the cost of a move, in units of the sphere's weight per unit of s
/// (split_moves). Rolling without
/// slipping lets the frictional LP move at no energy cost (a sphere on two others rolls
/// about the axis through its contacts); taken, such moves wander from vertex to vertex
/// and find second-order instabilities: a tripod took 2,603 LPs and at μ = 1 never ended
/// (5,000). With the cost it takes 3–8. A sphere balanced but for a force below this
/// stays, so the certificate's residual is below it too (10⁻⁶·wᵢ ≪ 10⁻³ m·g).
constexpr double kNeutralPenalty = 1e-6;

/// Sphere i's scaled displacement from the LP's columns.
std::array<double, 3> displacement(const std::vector<double>& u, std::size_t i,
                                   std::size_t columns) {
    const std::size_t c = columns * i;
    return {u[c], u[c + 1], u[c + 2]};
}

/// The basis of the last LP, to warm-start the next.
struct Basis {
    std::vector<ClpSimplex::Status> columns;
    std::unordered_map<RowKey, ClpSimplex::Status, RowKeyHash> rows;
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
/// cannot use it; false when no start gives a feasible optimum (CLP's numerical trouble
/// with nearly parallel rows, seen with frictional rows at mixed sizes).
bool solve_step(ClpSimplex& model, const Step& st, const Basis& basis, Start start,
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
        for (std::size_t r = 0; r < st.row_key.size(); ++r) {
            const auto it = basis.rows.find(st.row_key[r]);
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
        // simplex from the slack basis took 10,800–86,800 (notes/relax-certified-2026-12-06.md).
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
            const bool solved =
                solve_step(fresh, st, basis, warm ? Start::ValuesPass : Start::Slack, stats);
            model = fresh;
            return solved;
        }
        return false;
    }
    return true;
}

void save_basis(const ClpSimplex& model, const Step& st, Basis& basis) {
    basis.columns.resize(st.objective.size());
    for (std::size_t k = 0; k < basis.columns.size(); ++k) {
        basis.columns[k] = model.getColumnStatus(static_cast<int>(k));
    }
    basis.rows.clear();
    for (std::size_t r = 0; r < st.row_key.size(); ++r) {
        basis.rows.emplace(st.row_key[r], model.getRowStatus(static_cast<int>(r)));
    }
}

/// The contact forces of a frictionless step's LP optimum (see the header): pair rows' −y,
/// and the reduced costs of columns held by a wall or the floor.
std::vector<ContactForce> lp_forces(const ClpSimplex& model, const Step& st) {
    std::vector<ContactForce> forces;
    const double* y = model.dualRowSolution();
    for (std::size_t r = 0; r < st.row_key.size(); ++r) {
        if (-y[r] > 0.0) {
            forces.push_back({static_cast<std::size_t>(st.row_key[r].contact >> 32),
                              static_cast<std::size_t>(st.row_key[r].contact & 0xFFFFFFFFU),
                              Partner::Sphere, -y[r]});
        }
    }
    const double* z = model.getReducedCost();
    constexpr std::array<std::pair<Partner, Partner>, kMoves> walls{
        {{Partner::XMin, Partner::XMax},
         {Partner::Floor, Partner::Floor},
         {Partner::ZMin, Partner::ZMax}}};
    for (std::size_t col = 0; col < st.objective.size(); ++col) {
        const auto [low, high] = walls[col % kMoves];
        const std::size_t sphere = col / kMoves;
        if (z[col] > 0.0 && st.col_lower[col] > -1.0) {  // held from below by a wall
            forces.push_back({sphere, 0, low, z[col]});
        } else if (z[col] < 0.0 && st.col_upper[col] < 1.0 && col % kMoves != 1) {
            forces.push_back({sphere, 0, high, -z[col]});
        }
    }
    return forces;
}

/// Throws std::invalid_argument on a diameter, trust region or friction out of range.
void check_settle_arguments(double diameter, const SettleOptions& options) {
    if (!(diameter > 0.0) || !(options.trust_min > 0.0) ||
        !(options.trust_start >= options.trust_min) ||
        !(options.trust_max >= options.trust_start) ||
        (options.friction && !(*options.friction >= 0.0 && std::isfinite(*options.friction)))) {
        throw std::invalid_argument("settle_hard_spheres: bad diameter, trust region or friction");
    }
}

/// The pack in units of d: its spheres, their weights (2r)³ and the container.
struct ScaledPack {
    std::vector<Ball> balls;
    std::vector<double> weight;
    Container box;
};

/// `particles` and `container` in units of `diameter`.
ScaledPack scaled_pack(const std::vector<Particle>& particles, const Container& container,
                       double diameter) {
    const std::size_t n = particles.size();
    ScaledPack pack{std::vector<Ball>(n), std::vector<double>(n),
                    Container{container.x_min / diameter, container.x_max / diameter,
                              container.z_min / diameter, container.z_max / diameter,
                              container.floor / diameter, container.periodic}};
    for (std::size_t i = 0; i < n; ++i) {
        const Particle& p = particles[i];
        pack.balls[i] = {p.center.x() / diameter, p.center.y() / diameter, p.center.z() / diameter,
                         p.radius / diameter};
        pack.weight[i] = std::pow(2.0 * pack.balls[i].r, 3);
    }
    return pack;
}

/// The largest trust region: `trust_max`, and with periodic sides below
/// (period/2 − 2·r_max)/(2√3), since a pair's rows come from its nearest image alone, so no
/// other image may come within a step's reach 2·r_max + 2√3·s.
double largest_trust(const ScaledPack& pack, double trust_max) {
    if (!pack.box.periodic) {
        return trust_max;
    }
    double r_max = 0.0;
    for (const Ball& b : pack.balls) {
        r_max = std::max(r_max, b.r);
    }
    const double period =
        std::min(pack.box.x_max - pack.box.x_min, pack.box.z_max - pack.box.z_min);
    return std::min(trust_max, (0.5 * period - 2.0 * r_max) / (2.0 * std::sqrt(3.0)));
}

/// The step's moves `u` when no pair can meet: each sphere falls as far as it may; a sphere
/// resting on the floor carries its weight there (frictionless forces only).
void free_fall_moves(const Step& built, std::size_t columns, const ScaledPack& pack,
                     const SettleOptions& options, std::vector<double>& u, Basis& basis,
                     SettleStats& stats) {
    const std::size_t n = pack.balls.size();
    for (std::size_t i = 0; i < n; ++i) {
        u[columns * i + 1] = built.col_lower[columns * i + 1];
    }
    basis.columns.clear();
    stats.forces.clear();
    for (std::size_t i = 0; i < n && !options.friction; ++i) {
        if (built.col_lower[columns * i + 1] > -1.0) {
            stats.forces.push_back({i, 0, Partner::Floor, pack.weight[i]});
        }
    }
}

/// The step's moves `u` from the LP `st` (warm-started from `basis`, which keeps the new
/// basis), with a split move's two halves joined under `penalty` > 0, and the frictionless
/// contact forces; false when the solver fails.
bool lp_moves(ClpSimplex& model, const Step& st, std::size_t count, double penalty,
              const SettleOptions& options, std::vector<double>& u, Basis& basis,
              SettleStats& stats) {
    if (!solve_step(model, st, basis, Start::Warm, stats)) {
        return false;
    }
    if (penalty > 0.0) {
        const double* x = model.primalColumnSolution();
        for (std::size_t k = 0; k < count; ++k) {
            u[k] = x[2 * k] - x[2 * k + 1];
        }
    } else {
        std::copy_n(model.primalColumnSolution(), count, u.begin());
    }
    save_basis(model, st, basis);
    if (!options.friction && penalty == 0.0) {
        stats.forces = lp_forces(model, st);
    }
    return true;
}

/// Moves the spheres by trust·u; returns the energy dropped and counts in `falling` the
/// spheres held by the trust region on their way down.
double apply_moves(ScaledPack& pack, const std::vector<double>& u, std::size_t columns,
                   double trust, std::size_t& falling) {
    double drop = 0.0;
    for (std::size_t i = 0; i < pack.balls.size(); ++i) {
        const auto [ux, uy, uz] = displacement(u, i, columns);
        pack.balls[i].x += trust * ux;
        pack.balls[i].y += trust * uy;
        pack.balls[i].z += trust * uz;
        drop -= pack.weight[i] * trust * uy;
        falling += uy <= -1.0 + 1e-6 ? 1 : 0;
    }
    return drop;
}

/// The trust region of the settling's steps: doubled while many spheres fall freely or after
/// kSteadySteps steady steps, quartered when a step stalls.
class TrustRegion {
  public:
    TrustRegion(double start, double largest) : trust_(std::min(start, largest)), max_(largest) {}

    double size() const { return trust_; }

    /// The next step's region after one that dropped `drop` with `falling` of `n` spheres
    /// falling freely (unchanged after a still step).
    void update(bool still, std::size_t falling, std::size_t n, double drop) {
        if (still) {
            // No move lowers the energy by more than it costs: the end.
        } else if (static_cast<double>(falling) > kSlidingShare * static_cast<double>(n)) {
            trust_ = std::min(2.0 * trust_, max_);
            steady_ = 0;
        } else if (drop < kStallRate * trust_) {
            trust_ /= 4.0;
            steady_ = 0;
        } else if (++steady_ >= kSteadySteps) {
            trust_ = std::min(2.0 * trust_, max_);
            steady_ = 0;
        }
    }

  private:
    double trust_;
    double max_;
    int steady_ = 0;  // steps in a row at this trust region (kSteadySteps)
};

/// Writes the settled positions back (wrapped when periodic) and the largest move, in d.
void write_back(const ScaledPack& pack, const std::vector<Ball>& start, const Container& container,
                double diameter, std::vector<Particle>& particles, SettleStats& stats) {
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Ball& b = pack.balls[i];
        const double dx = b.x - start[i].x;
        const double dy = b.y - start[i].y;
        const double dz = b.z - start[i].z;
        stats.move_max = std::max(stats.move_max, std::sqrt(dx * dx + dy * dy + dz * dz));
        particles[i].center =
            container.wrapped(Vec3(b.x * diameter, b.y * diameter, b.z * diameter));
    }
}

}  // namespace

bool lp_solver_available() {
    return true;
}

SettleStats settle_hard_spheres(std::vector<Particle>& particles, const Container& container,
                                double diameter, const SettleOptions& options) {
    check_settle_arguments(diameter, options);
    SettleStats stats;
    const std::size_t n = particles.size();
    if (n == 0) {
        return stats;
    }
    ScaledPack pack = scaled_pack(particles, container, diameter);  // in units of d
    const std::vector<Ball> start = pack.balls;
    const std::size_t columns = columns_per_sphere(options);
    const double penalty = options.friction ? kNeutralPenalty : 0.0;
    TrustRegion trust(options.trust_start, largest_trust(pack, options.trust_max));
    NeighbourList list;
    Basis basis;
    ClpSimplex model;
    model.setLogLevel(0);
    while (stats.iterations < options.max_iterations) {
        list.build(pack.balls, 2.0 * std::sqrt(3.0) * trust.size(), pack.box);
        const Step built =
            build_step(pack.balls, list, pack.box, trust.size(), pack.weight, options);
        const Step st = penalty > 0.0 ? split_moves(built, penalty, pack.weight, columns) : built;
        std::vector<double> u(columns * n);
        if (st.row_key.empty()) {
            free_fall_moves(built, columns, pack, options, u, basis, stats);
        } else if (!lp_moves(model, st, columns * n, penalty, options, u, basis, stats)) {
            stats.solver_failed = true;  // the pack is left as the last step made it
            break;
        }
        ++stats.iterations;
        std::size_t falling = 0;
        const double drop = apply_moves(pack, u, columns, trust.size(), falling);
        stats.energy_drop += drop;
        const bool still =
            penalty > 0.0 && std::all_of(u.begin(), u.end(), [](double v) { return v == 0.0; });
        trust.update(still, falling, n, drop);
        if (options.progress) {
            options.progress(stats.iterations, trust.size());
        }
        if (still || trust.size() < options.trust_min) {
            stats.converged = true;
            stats.ended_still = still;
            break;
        }
    }
    write_back(pack, start, container, diameter, particles, stats);
    return stats;
}

}  // namespace sgmp::engine
