#pragma once
/// @file equivalence.hpp
/// The equivalence test behind every verdict: is a difference inside a declared margin m,
/// outside it, or not yet known?
///
/// Scalars. Δ̂ = x̄_A − x̄_B with Student's pooled standard error (Schuirmann's TOST)
/// SE = s_p·√(1/n_A + 1/n_B), s_p² = ((n_A − 1)s_A² + (n_B − 1)s_B²)/(n_A + n_B − 2),
/// ν = n_A + n_B − 2: the seed-to-seed scatter is estimated from both groups, so a
/// candidate of 1–2 packs is not left with ν ≈ 1 (Welch's ν collapses there); a candidate
/// of one pack takes the reference's sd. The 90 % interval Δ̂ ± t₀.₉₅,ν·SE is the two
/// one-sided tests (TOST) at α = 5 %:
///   agree   when the interval lies inside [−m, m]   (p_agree  = P(t_ν > (m − |Δ̂|)/SE) ≤ α),
///   differ  when it lies wholly beyond ±m            (p_differ = P(t_ν > (|Δ̂| − m)/SE) ≤ α),
///   inconclusive otherwise (it straddles a margin).
/// A verdict is never changed afterwards.
///
/// Curves (a distance D ≥ 0 between two mean curves, declared margin m on the true
/// distance D*). The noise of the mean difference per bin k has variance
/// v_k = s_A,k²/n_A + s_B,k²/n_B; by the triangle inequality |D̂ − D*| ≤ ‖ε‖, the norm of
/// that noise. For the L2 distance of g(r), ‖ε‖² = Σ w v_k χ²₁ ≈ a·χ²_f (Satterthwaite:
/// a = Σλ²/Σλ, f = (Σλ)²/Σλ², λ_k = w·v_k); for the total-variation distance of P(Z),
/// ½Σ|ε_k| is taken as normal with mean ½Σ√(2v_k/π) and variance ¼Σ v_k(1 − 2/π). With
/// q_α the (1 − α) quantile of the noise norm, the interval is [max(0, D̂ − q), D̂ + q]:
/// agree when D̂ + q ≤ m, differ when D̂ − q > m (conservative: the bound is a worst case).
///
/// Power, as a minimum detectable difference: the true |Δ| the test calls `differ` with
/// probability 80 %, mdd = m + (t₀.₉₅,ν + t₀.₈₀,ν)·SE (curves: m + q₀.₀₅ + q₀.₂₀).
/// An inconclusive verdict says how many seeds per side, at the same sds and estimate,
/// would decide it (seeds_to_decide; none when no count up to 1000 would).

#include <cstddef>
#include <optional>
#include <vector>

namespace sgmp::compare {

/// The level of every one-sided test (the interval is 1 − 2α = 90 %).
inline constexpr double kTestAlpha = 0.05;

enum class Decision { Agree, Differ, Inconclusive };

struct EquivalenceResult {
    double estimate = 0.0;  // Δ̂ (scalars) or D̂ (curves)
    double margin = 0.0;
    double ci_low = 0.0;
    double ci_high = 0.0;
    double standard_error = 0.0;  // scalars: SE; curves: q₀.₀₅ / 1.645
    double degrees_of_freedom = 0.0;
    double p_agree = 1.0;   // of H0: |Δ| ≥ m
    double p_differ = 1.0;  // of H0: |Δ| ≤ m
    double mdd = 0.0;
    Decision decision = Decision::Inconclusive;
    std::optional<std::size_t> seeds_to_decide;  // per side, for an inconclusive result
};

/// The sample of one group for a scalar: mean, sample sd (n − 1) and n.
struct ScalarSample {
    double mean = 0.0;
    double sd = 0.0;
    std::size_t n = 0;
};
/// Mean and sample sd (n − 1) of `values`.
ScalarSample sample_of(const std::vector<double>& values);

/// The scalar test of the candidate against the reference (header). Needs n_B ≥ 2 or
/// n_A ≥ 2 with n_B ≥ 1; otherwise the result is inconclusive with an infinite interval.
EquivalenceResult test_scalar(const ScalarSample& candidate, const ScalarSample& reference,
                              double margin);

enum class CurveNorm { L2, TotalVariation };

/// Per bin, the variance of the mean difference: s_A,k²/n_A + s_B,k²/n_B (a candidate of
/// one pack takes the reference's s_k). Curves of unequal length are padded with zeros.
std::vector<double> noise_variance(const std::vector<std::vector<double>>& candidate,
                                   const std::vector<std::vector<double>>& reference);

/// The curve test (header): observed distance `distance`, the per-bin variances of the
/// noise `variance` (weighted by `bin_weight`, the bin width for L2), the norm;
/// `seeds_now` the smaller group's pack count (seeds_to_decide scales the variances by it).
EquivalenceResult test_curve(double distance, const std::vector<double>& variance,
                             double bin_weight, CurveNorm norm, double margin,
                             std::size_t seeds_now);

}  // namespace sgmp::compare
