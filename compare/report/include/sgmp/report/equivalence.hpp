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
/// g(r), L2 distance ‖Δ‖ = (Σ_k w Δ_k²)^½ of the true mean curves on K bins of width w
/// (after Dette, Möllenhoff, Volgushev & Bretz 2018, JASA 113:711, an estimate of the squared
/// distance with its variance). Δ̂_k = ḡ_A,k − ḡ_B,k; v̂_k = s_A,k²/n_A + s_B,k²/n_B, each
/// group at its own sd (the classes' scatter differs by up to 40 %; a group of one pack takes
/// the other's s_k², assuming it scatters alike). U = D̂² − w Σ v̂_k is unbiased for ‖Δ‖².
/// At ‖Δ‖ = θ, with independent normal bins,
///   Var U  = 4w² Σ Δ_k² v_k + 2w² Σ v_k² + w² Σ Var v̂_k
///          ≤ δ (4w λ θ² + 2w² Σ v_k² + w² Σ Var v̂_k),
///   κ₃ U   = 8w³ Σ v_k³ + 24w³ Σ Δ_k² v_k² − w³ Σ κ₃ v̂_k,  24w³ Σ Δ_k² v_k² ∈ [0, 24w² λ² θ²];
/// the linear terms are bounded for every direction of Δ by λ = max_k v̂_k (w Σ Δ_k² v_k ≤ λθ²;
/// no plug-in of Δ̂), v_k², v_k³ estimated without bias (σ⁴ = s⁴f/(f+2), σ⁶ = s⁶f²/((f+2)(f+4))
/// at f degrees of freedom), Var v̂_k = Σ 2c²σ⁴/f and κ₃ v̂_k = Σ 8c³σ⁶/f² over the groups'
/// terms c·s². δ = kL2DesignEffect covers the bins' measured correlation (below). U's
/// quantiles are Cornish–Fisher's q_p(θ) = θ² + σ z_p + (z_p² − 1) κ₃ / (6σ²), with the
/// smaller κ₃ bound (δ⁰ on the first term, δ² on the last) on the agree side and the larger
/// (δ² on the first two) on the differ side. The one-sided 95 % bounds on ‖Δ‖ invert them:
/// ci_high = the largest θ with U ≥ q₀.₀₅(θ) (0 when U < q₀.₀₅(θ) for all θ), ci_low = the
/// smallest θ with U ≤ q₀.₉₅(θ); agree when ci_high < m, differ when ci_low > m; p_agree and
/// p_differ are the Cornish–Fisher tail probabilities of U at θ = m. Power: mdd is the θ at
/// which U's 20 % quantile reaches q₀.₉₅(m). Monte Carlo (l2_equivalence_test.cpp) holds both
/// errors ≤ 5 % at θ = m for spike, block, flat and smooth Δ.
///
/// P(Z), total variation D = ½ Σ|p_A − p_B| (a distance whose noise is bounded by the triangle
/// inequality |D̂ − D*| ≤ ‖ε‖_TV, with v_k as above): ½Σ|ε_k| is taken as normal with mean
/// ½Σ√(2v_k/π) and variance ¼Σ v_k(1 − 2/π); with q_α its (1 − α) quantile the interval is
/// [max(0, D̂ − q), D̂ + q]: agree when D̂ + q ≤ m, differ when D̂ − q > m (conservative: the
/// bound is a worst case).
///
/// Power, as a minimum detectable difference: the true |Δ| the test calls `differ` with
/// probability 80 %, mdd = m + (t₀.₉₅,ν + t₀.₈₀,ν)·SE (TV: m + q₀.₀₅ + q₀.₂₀; L2 above).
/// An inconclusive verdict says how many seeds per side, at the same sds and estimate,
/// would decide it (seeds_to_decide; none when no count up to 1000 would).

#include <cstddef>
#include <optional>
#include <vector>

namespace sgmp::report {

/// The level of every one-sided test (the interval is 1 − 2α = 90 %).
inline constexpr double kTestAlpha = 0.05;

/// The design effect δ on the variance of the L2 test's U (header): the bins of g(r) are not
/// exactly independent. Measured on the stored DEM pours (data/reference/, N = 1002–9000, 10–12
/// pooled within-class degrees of freedom a count, 0.02 d bins on [1.1, 5] d): neighbour
/// correlations −0.03 … +0.02 (null sd 0.02), sums of 4 bins scatter 0.83–1.08 times their
/// independent-bin variance, tr Σ² / Σ v_k² (unbiased) 0.90–1.37 (null 1.00 ± 0.16), and the
/// 2-against-3 splits of each class give E[U² / Var U] = 1.18. 1.4 covers the largest.
inline constexpr double kL2DesignEffect = 1.4;

enum class Decision { Agree, Differ, Inconclusive };

struct EquivalenceResult {
    double estimate = 0.0;  // Δ̂ (scalars) or D̂ (curves)
    double margin = 0.0;
    double ci_low = 0.0;
    double ci_high = 0.0;
    double standard_error = 0.0;  // scalars: SE; TV: q₀.₀₅ / 1.645; L2: √Var U at m, over 2m
    double degrees_of_freedom = 0.0;  // scalars: ν; L2: of the noise level w Σ v̂_k, 2t²/Var t
    double p_agree = 1.0;             // of H0: |Δ| ≥ m
    double p_differ = 1.0;            // of H0: |Δ| ≤ m
    double mdd = 0.0;
    /// The upper bound an estimate of no difference would give (scalars: t·SE; TV: q; L2:
    /// ci_high at U = 0): agreement is reachable at these n only when it is below the margin.
    double zero_bound = 0.0;
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
/// `alpha` is the one-sided level (the interval 1 − 2α); a group-sequential look passes its
/// nominal level (group_sequential.hpp).
EquivalenceResult test_scalar(const ScalarSample& candidate, const ScalarSample& reference,
                              double margin, double alpha = kTestAlpha);

/// Per bin, the variance of the mean difference: s_A,k²/n_A + s_B,k²/n_B (a candidate of
/// one pack takes the reference's s_k). Curves of unequal length are padded with zeros.
std::vector<double> noise_variance(const std::vector<std::vector<double>>& candidate,
                                   const std::vector<std::vector<double>>& reference);

/// The L2 test (header) of two groups of curves on common bins of width `bin_width`
/// (curves of unequal length padded with zeros). Needs one group of ≥ 2 curves and the other
/// of ≥ 1; otherwise the result is inconclusive with an infinite interval.
EquivalenceResult test_l2_curves(const std::vector<std::vector<double>>& candidate,
                                 const std::vector<std::vector<double>>& reference,
                                 double bin_width, double margin, double alpha = kTestAlpha);

/// Whether the L2 test at one-sided level `alpha` would decide (agree or differ) with
/// `candidate_n` and `reference_n` curves, each group scattering as it does now and the
/// estimate of ‖Δ‖² (U) unchanged: what a group-sequential row asks of more seeds or pours.
bool l2_decides_with(const std::vector<std::vector<double>>& candidate,
                     const std::vector<std::vector<double>>& reference, double bin_width,
                     double margin, double alpha, std::size_t candidate_n, std::size_t reference_n);

/// The total-variation test (header): observed distance `distance`, the per-bin variances of
/// the noise `variance`; `seeds_now` the smaller group's pack count (seeds_to_decide scales
/// the variances by it).
EquivalenceResult test_total_variation(double distance, const std::vector<double>& variance,
                                       double margin, std::size_t seeds_now,
                                       double alpha = kTestAlpha);

}  // namespace sgmp::report
