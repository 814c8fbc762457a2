#pragma once
/// @file group_sequential.hpp
/// The group-sequential design of the equivalence tests: candidate (SGMP) seeds are added in
/// blocks against a fixed reference set, and the tests look at the data after each block.
///
/// Looks. The first look is at n₁ candidate seeds, then every `block` seeds, the last at
/// N = max_seeds (n₁, n₁ + b, n₁ + 2b, …, N); a group that holds n seeds off that grid
/// looks at n as well (an unplanned look: the spending function takes it as it comes).
///
/// Information. With the reference's n_B fixed and one seed-to-seed σ (the pooled test's
/// assumption), Var Δ̂ = σ²(1/n + 1/n_B): the information at n candidate seeds is
/// I(n) = 1/(1/n + 1/n_B) and its fraction t = I(n)/I(N). It stays bounded as n grows (the
/// reference's share of the variance stays), so the first look keeps a fraction of at least
/// n_B⁻¹/(n₁⁻¹ + n_B⁻¹) however large N is.
///
/// Spending. Each one-sided test (of the two of TOST, and the differ test) spends its
/// α = 5 % over the looks by the Lan–DeMets O'Brien–Fleming-type function
///   α(t) = 2·(1 − Φ(z₁₋α/₂ / √t)),   α(1) = α,
/// so the cumulative chance of a wrong rejection by look k is α(t_k) (Lan & DeMets 1983,
/// Biometrika 70:659). The boundary c_k of the standardised statistics Z_k (canonical joint
/// law: Z_j, Z_k normal with corr √(I_j/I_k)) solves
///   P(Z₁ ≤ c₁, …, Z_{k−1} ≤ c_{k−1}, Z_k > c_k) = α(t_k) − α(t_{k−1}),
/// found by recursive numerical integration (Armitage, McPherson & Rowe 1969; Jennison &
/// Turnbull 2000, ch. 19) on the score S_k = Z_k·√I_k, a Gaussian random walk under H0: its
/// sub-probability on the continuation region is a histogram on one fixed grid (cells
/// kBoundaryCell·√I₁ wide), moved to the next look by the increment's kernel with its exact
/// variance (normal cell masses with Sheppard's correction, or a three-point kernel for an
/// increment narrower than a cell, as late looks against a fixed reference are). The test at
/// look k of a curve test runs at the nominal one-sided level α_k = 1 − Φ(c_k) (its normal
/// quantile is c_k).
///
/// Scalars. The pooled Student statistics T_k = (Δ̂_k − m)/SE_k share the reference's mean
/// and variance estimate across looks, and matching nominal p-values (t_ν(1 − α_k), Jennison
/// & Turnbull §11.5) spends too much with few reference pours (measured: 5.5 % instead of 5 %
/// against 5 pours, 5.1 % against 20). Their joint law under H0 is free of σ and of the means,
/// so the boundaries c_k^T are found on that law itself: 200,000 simulated paths (fixed seed,
/// sgmp::Random), c_k^T the value that the paths not yet stopped exceed in the share
/// α(t_k) − α(t_{k−1}) of all paths. The scalar test at look k runs at the level
/// P(t_ν > c_k^T), ν = n_k + n_B − 2 (so its t quantile is c_k^T).

#include <cstddef>
#include <map>
#include <mutex>
#include <tuple>
#include <vector>

namespace sgmp::report {

/// The width of the histogram's cells, in units of the first look's sd of S.
inline constexpr double kBoundaryCell = 0.01;
/// The grid's floor, in sd of S at the last look (P(Z < −8.5) ≈ 10⁻¹⁷: never back).
inline constexpr double kBoundaryFloor = -8.5;
/// The largest boundary used: a look whose spent α is below 1 − Φ(12) rejects nothing.
inline constexpr double kBoundaryCeiling = 12.0;

/// How candidate seeds are added (group_sequential.hpp).
struct SequentialDesign {
    std::size_t first_look = 5;  // n₁: the seeds the first look sees
    std::size_t block = 5;       // seeds added between looks
    std::size_t max_seeds = 50;  // N: the last look
    double alpha = 0.05;         // one-sided level of each test over all looks
};

/// Lan–DeMets O'Brien–Fleming-type spending: α spent by information fraction t ∈ [0, 1].
double spent_alpha(double t, double alpha);

/// Information of n candidate seeds against n_B reference pours: 1/(1/n + 1/n_B).
double information(std::size_t candidate_n, std::size_t reference_n);

/// The looks a group of `available` candidate seeds has taken (n₁ … up to `available`,
/// `available` itself last) followed by the looks still planned, up to the design's last
/// (max(N, available)).
std::vector<std::size_t> look_schedule(const SequentialDesign& design, std::size_t available);

/// One look of a design.
struct Look {
    std::size_t candidate_n = 0;
    double fraction = 0.0;       // t_k = I(n_k)/I(N)
    double alpha_spent = 0.0;    // α(t_k), cumulative
    double boundary = 0.0;       // c_k (Z scale)
    double nominal_alpha = 0.0;  // 1 − Φ(c_k): the curves' level
    /// The scalars' level: P(t_ν > c_k^T) at ν = n_k + n_B − 2, c_k^T the boundary of the
    /// pooled Student statistics that spends α(t_k) (header).
    double student_alpha = 0.0;
};

/// The boundaries of the looks at `candidate_n` (increasing) against `reference_n` pours;
/// the last entry is the design's last look (fraction 1). Throws std::invalid_argument on
/// an empty or non-increasing list or a zero count.
std::vector<Look> boundaries(const std::vector<std::size_t>& candidate_n, std::size_t reference_n,
                             double alpha);

/// boundaries() remembered by their arguments (crossval asks for the same few many times);
/// safe to share between threads.
class BoundaryCache {
  public:
    std::vector<Look> get(const std::vector<std::size_t>& candidate_n, std::size_t reference_n,
                          double alpha);

  private:
    std::mutex mutex_;
    std::map<std::tuple<std::vector<std::size_t>, std::size_t, double>, std::vector<Look>> cache_;
};

}  // namespace sgmp::report
