// The LP of one iteration of the hard-sphere settling (hard_sphere_settle_step.hpp).
#include "hard_sphere_settle_step.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "sgmp/engine/coulomb_pyramid.hpp"

namespace sgmp::engine::settle_step {
namespace {

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

}  // namespace

/// The LP of one iteration at trust region `trust` (units of d): a non-overlap row for each
/// listed pair within the step's reach 2√3·trust (with friction, the pyramid's edge rows of
/// each pair and wall within `trust`), each column bounded by the trust region and the walls,
/// and the weights as the objective.
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

}  // namespace sgmp::engine::settle_step
