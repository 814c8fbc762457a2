#pragma once
/// @file hard_sphere_settle_step.hpp
/// The LP of one iteration of the hard-sphere settling (hard_sphere_settle.cpp): its rows
/// (non-overlap, or with friction the Coulomb pyramid's edges), columns, bounds and
/// objective. Internal to the engine.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "sgmp/engine/hard_sphere_settle.hpp"
#include "sgmp/engine/neighbour_list.hpp"

namespace sgmp::engine::settle_step {

/// A row of the LP: its contact (contact_key) and, for a frictional contact, the
/// edge of its pyramid (kNormalRow for a plain non-overlap row).
struct RowKey {
    std::uint64_t contact = 0;
    std::uint32_t edge = 0;
    bool operator==(const RowKey&) const = default;
};
inline constexpr std::uint32_t kNormalRow = 0xFFU;
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
inline constexpr std::size_t kMoves = 3;
inline std::size_t columns_per_sphere(const SettleOptions& options) {
    return options.friction ? 6 : 3;
}

/// The LP of one iteration at trust region `trust` (units of d): a non-overlap row for each
/// listed pair within the step's reach 2√3·trust (with friction, the pyramid's edge rows of
/// each pair and wall within `trust`), each column bounded by the trust region and the walls,
/// and the weights as the objective.
Step build_step(const std::vector<Ball>& balls, const NeighbourList& list, const Container& box,
                double trust, const std::vector<double>& weight, const SettleOptions& options);

/// The step with each move u = p − q split into p, q ≥ 0, both at cost penalty·wᵢ (wᵢ the
/// sphere's weight) beside u's own: a move that lowers no energy costs penalty·wᵢ·|u| and
/// is not taken. Columns 2k and 2k + 1 are u_k's p and q.
Step split_moves(const Step& st, double penalty, const std::vector<double>& weight,
                 std::size_t columns);

}  // namespace sgmp::engine::settle_step
