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

#include "sgmp/engine/coulomb_pyramid.hpp"
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

/// A row of the LP: its contact (contact_key) and, for a frictional contact, the
/// edge of its pyramid (kNormalRow for a plain non-overlap row).
struct RowKey {
    std::uint64_t contact = 0;
    std::uint32_t edge = 0;
    bool operator==(const RowKey&) const = default;
};
constexpr std::uint32_t kNormalRow = 0xFFU;
struct RowKeyHash {
    std::size_t operator()(const RowKey& k) const {
        return std::hash<std::uint64_t>{}(k.contact * 16U + k.edge);
    }
};

/// The LP of one iteration in the scaled variables u = Δ/s (units of d), and the pairs of
/// its rows.
struct Step {
    std::vector<int> row_index;
    std::vector<int> col_index;
    std::vector<double> element;
    std::vector<double> row_upper;
    std::vector<RowKey> row_key;
    std::vector<double> col_lower;
    std::vector<double> col_upper;
    std::vector<double> objective;
};

/// Columns of sphere i: its scaled moves along x, y and z, then (frictional) its scaled
/// rotation ψ = θ/(2·s) about x, y and z (θ in radians: a sphere of diameter d turning by θ
/// moves its surface by at most s·|ψ|·d).
constexpr std::size_t kMoves = 3;
std::size_t columns_per_sphere(const SettleOptions& options) {
    return options.friction ? 6 : 3;
}

/// Appends rows to a Step: `add` puts a coefficient of one column into the open row,
/// `close` ends it with its bound and key.
struct RowWriter {
    Step& st;
    int row = 0;
    void add(std::size_t column, double value) {
        if (value == 0.0) {
            return;  // no explicit zeros: CLP may pivot on them
        }
        st.row_index.push_back(row);
        st.col_index.push_back(static_cast<int>(column));
        st.element.push_back(value);
    }
    void add(std::size_t first_column, const Vec3& v) {
        for (int a = 0; a < 3; ++a) {
            add(first_column + static_cast<std::size_t>(a), v[a]);
        }
    }
    void close(double upper, RowKey key) {
        st.row_upper.push_back(upper);
        st.row_key.push_back(key);
        ++row;
    }
};

/// The frictional rows of one contact of sphere i with partner j (j = none for a wall):
/// for each pyramid edge E around the normal N pushing i away from its partner,
/// E·(uᵢ − uⱼ at the contact point) ≥ −gap, in the scaled columns:
///     −E·uᵢ + 2rᵢ·(N×E)·ψᵢ + E·uⱼ + 2rⱼ·(N×E)·ψⱼ ≤ gap/s
/// (the rotation terms move the contact point; see the header for the duality).
void frictional_rows(RowWriter& w, std::size_t columns, std::size_t i, const Ball* partner,
                     std::size_t j, const Vec3& normal, double radius_i, double upper,
                     std::uint64_t contact, const SettleOptions& options,
                     std::vector<char>& turns) {
    const auto edges = coulomb_pyramid(normal, *options.friction);
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const Vec3& edge = edges[k];
        const Vec3 moment = normal.cross(edge);
        w.add(columns * i, -edge);
        w.add(columns * i + kMoves, 2.0 * radius_i * moment);
        if (partner != nullptr) {
            w.add(columns * j, edge);
            w.add(columns * j + kMoves, 2.0 * partner->r * moment);
        }
        w.close(upper, {contact, static_cast<std::uint32_t>(k)});
    }
    turns[i] = 1;
    if (partner != nullptr) {
        turns[j] = 1;
    }
}

Step build_step(const std::vector<Ball>& balls, const NeighbourList& list, const Container& box,
                double trust, const std::vector<double>& weight, const SettleOptions& options) {
    Step st;
    RowWriter w{st};
    const std::size_t n = balls.size();
    const std::size_t columns = columns_per_sphere(options);
    const double cutoff = 2.0 * std::sqrt(3.0) * trust;
    std::vector<char> turns(n, 0);  // spheres with a frictional contact may turn
    for (std::size_t i = 0; i < n; ++i) {
        for (const std::uint32_t j : list.of(i)) {
            double dx = balls[j].x - balls[i].x;
            double dz = balls[j].z - balls[i].z;
            box.to_nearest_image(dx, dz);
            const Vec3 d(dx, balls[j].y - balls[i].y, dz);
            const double dist = d.norm();
            const double gap = dist - balls[i].r - balls[j].r;
            if (gap >= cutoff || dist == 0.0) {
                continue;
            }
            const RowKey key{contact_key(i, j, Partner::Sphere), kNormalRow};
            if (options.friction && gap <= trust) {
                frictional_rows(w, columns, i, &balls[j], j, -d / dist, balls[i].r, gap / trust,
                                key.contact, options, turns);
                continue;
            }
            w.add(columns * i, d / dist);
            w.add(columns * j, -d / dist);
            w.close(gap / trust, key);
        }
    }
    st.col_lower.assign(columns * n, -1.0);
    st.col_upper.assign(columns * n, 1.0);
    st.objective.assign(columns * n, 0.0);
    const auto clamp = [&](std::size_t col, double lo, double hi) {
        st.col_upper[col] = std::min(1.0, hi / trust);
        st.col_lower[col] = std::min(std::max(-1.0, lo / trust), st.col_upper[col]);  // rounding
    };
    for (std::size_t i = 0; i < n; ++i) {
        const Ball& b = balls[i];
        const std::size_t c = columns * i;
        if (!box.periodic) {
            clamp(c, box.x_min + b.r - b.x, box.x_max - b.r - b.x);
            clamp(c + 2, box.z_min + b.r - b.z, box.z_max - b.r - b.z);
        }
        clamp(c + 1, box.floor + b.r - b.y, 1e300);
        st.objective[c + 1] = weight[i];
        if (!options.friction) {
            continue;
        }
        for (const auto& [gap, normal, wall] : wall_gaps(Vec3(b.x, b.y, b.z), b.r, box)) {
            if (gap <= trust) {
                frictional_rows(w, columns, i, nullptr, 0, normal, b.r, std::max(gap, 0.0) / trust,
                                contact_key(i, 0, wall), options, turns);
            }
        }
    }
    for (std::size_t i = 0; options.friction && i < n; ++i) {
        for (std::size_t a = kMoves; a < columns && turns[i] == 0; ++a) {
            st.col_lower[columns * i + a] = 0.0;  // no contact to turn against: held still
            st.col_upper[columns * i + a] = 0.0;
        }
    }
    return st;
}

/// The step with each move u = p − q split into p, q ≥ 0, both at cost penalty·wᵢ (wᵢ the
/// sphere's weight) beside u's own: a move that lowers no energy costs penalty·wᵢ·|u| and
/// is not taken. Columns 2k and 2k + 1 are u_k's p and q.
Step split_moves(const Step& st, double penalty, const std::vector<double>& weight,
                 std::size_t columns) {
    Step out;
    out.row_upper = st.row_upper;
    out.row_key = st.row_key;
    for (std::size_t e = 0; e < st.element.size(); ++e) {
        for (const int half : {0, 1}) {
            out.row_index.push_back(st.row_index[e]);
            out.col_index.push_back(2 * st.col_index[e] + half);
            out.element.push_back(half == 0 ? st.element[e] : -st.element[e]);
        }
    }
    for (std::size_t k = 0; k < st.objective.size(); ++k) {
        const double lo = st.col_lower[k];
        const double hi = st.col_upper[k];
        out.col_lower.insert(out.col_lower.end(), {std::max(0.0, lo), std::max(0.0, -hi)});
        out.col_upper.insert(out.col_upper.end(), {std::max(0.0, hi), std::max(0.0, -lo)});
        const double cost = penalty * weight[k / columns];
        out.objective.insert(out.objective.end(),
                             {st.objective[k] + cost, -st.objective[k] + cost});
    }
    return out;
}

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

}  // namespace

bool lp_solver_available() {
    return true;
}

SettleStats settle_hard_spheres(std::vector<Particle>& particles, const Container& container,
                                double diameter, const SettleOptions& options) {
    if (!(diameter > 0.0) || !(options.trust_min > 0.0) ||
        !(options.trust_start >= options.trust_min) ||
        !(options.trust_max >= options.trust_start) ||
        (options.friction && !(*options.friction >= 0.0 && std::isfinite(*options.friction)))) {
        throw std::invalid_argument("settle_hard_spheres: bad diameter, trust region or friction");
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
                        container.floor / diameter, container.periodic};
    for (std::size_t i = 0; i < n; ++i) {
        const Particle& p = particles[i];
        balls[i] = {p.center.x() / diameter, p.center.y() / diameter, p.center.z() / diameter,
                    p.radius / diameter};
        weight[i] = std::pow(2.0 * balls[i].r, 3);
    }
    const std::vector<Ball> start = balls;
    const std::size_t columns = columns_per_sphere(options);
    const double penalty = options.friction ? kNeutralPenalty : 0.0;
    // With periodic sides a pair's rows come from its nearest image alone, so no other image
    // may come within a step's reach 2·r_max + 2√3·s: s stays below (period/2 − 2·r_max)/(2√3).
    double trust_max = options.trust_max;
    if (box.periodic) {
        double r_max = 0.0;
        for (const Ball& b : balls) {
            r_max = std::max(r_max, b.r);
        }
        const double period = std::min(box.x_max - box.x_min, box.z_max - box.z_min);
        trust_max = std::min(trust_max, (0.5 * period - 2.0 * r_max) / (2.0 * std::sqrt(3.0)));
    }
    double trust = std::min(options.trust_start, trust_max);
    int steady = 0;  // steps in a row at this trust region (kSteadySteps)
    NeighbourList list;
    Basis basis;
    ClpSimplex model;
    model.setLogLevel(0);
    while (stats.iterations < options.max_iterations) {
        list.build(balls, 2.0 * std::sqrt(3.0) * trust, box);
        const Step built = build_step(balls, list, box, trust, weight, options);
        const Step st = penalty > 0.0 ? split_moves(built, penalty, weight, columns) : built;
        std::vector<double> u(columns * n);
        if (st.row_key.empty()) {  // no pair can meet: each sphere falls as far as it may
            for (std::size_t i = 0; i < n; ++i) {
                u[columns * i + 1] = built.col_lower[columns * i + 1];
            }
            basis.columns.clear();
            stats.forces.clear();  // a sphere resting on the floor carries its weight there
            for (std::size_t i = 0; i < n && !options.friction; ++i) {
                if (built.col_lower[columns * i + 1] > -1.0) {
                    stats.forces.push_back({i, 0, Partner::Floor, weight[i]});
                }
            }
        } else {
            if (!solve_step(model, st, basis, Start::Warm, stats)) {
                stats.solver_failed = true;  // the pack is left as the last step made it
                break;
            }
            if (penalty > 0.0) {
                const double* x = model.primalColumnSolution();
                for (std::size_t k = 0; k < columns * n; ++k) {
                    u[k] = x[2 * k] - x[2 * k + 1];
                }
            } else {
                std::copy_n(model.primalColumnSolution(), columns * n, u.begin());
            }
            save_basis(model, st, basis);
            if (!options.friction && penalty == 0.0) {
                stats.forces = lp_forces(model, st);
            }
        }
        ++stats.iterations;
        double drop = 0.0;
        std::size_t falling = 0;  // spheres held by the trust region on their way down
        for (std::size_t i = 0; i < n; ++i) {
            const auto [ux, uy, uz] = displacement(u, i, columns);
            balls[i].x += trust * ux;
            balls[i].y += trust * uy;
            balls[i].z += trust * uz;
            drop -= weight[i] * trust * uy;
            falling += uy <= -1.0 + 1e-6 ? 1 : 0;
        }
        stats.energy_drop += drop;
        const bool still =
            penalty > 0.0 && std::all_of(u.begin(), u.end(), [](double v) { return v == 0.0; });
        if (still) {
            // No move lowers the energy by more than it costs: the end.
        } else if (static_cast<double>(falling) > kSlidingShare * static_cast<double>(n)) {
            trust = std::min(2.0 * trust, trust_max);
            steady = 0;
        } else if (drop < kStallRate * trust) {
            trust /= 4.0;
            steady = 0;
        } else if (++steady >= kSteadySteps) {
            trust = std::min(2.0 * trust, trust_max);
            steady = 0;
        }
        if (options.progress) {
            options.progress(stats.iterations, trust);
        }
        if (still || trust < options.trust_min) {
            stats.converged = true;
            stats.ended_still = still;
            break;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        const double dx = balls[i].x - start[i].x;
        const double dy = balls[i].y - start[i].y;
        const double dz = balls[i].z - start[i].z;
        stats.move_max = std::max(stats.move_max, std::sqrt(dx * dx + dy * dy + dz * dz));
        particles[i].center = container.wrapped(
            Vec3(balls[i].x * diameter, balls[i].y * diameter, balls[i].z * diameter));
    }
    return stats;
}

}  // namespace sgmp::engine
