#include "sgmp/report/equivalence.hpp"

#include "equivalence_detail.hpp"
#include "sgmp/report/statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <numbers>

namespace sgmp::report {
namespace {

using detail::first_seeds_to_try;
using detail::kMostSeeds;
using detail::kPowerQuantile;
using detail::undecidable;

double t_quantile(double p, double df) {
    return boost::math::quantile(boost::math::students_t(df), p);
}

double t_survival(double x, double df) {
    return boost::math::cdf(boost::math::complement(boost::math::students_t(df), x));
}

/// The decision of an interval against ±margin.
Decision decide(double low, double high, double margin) {
    if (low >= -margin && high <= margin) {
        return Decision::Agree;
    }
    if (low > margin || high < -margin) {
        return Decision::Differ;
    }
    return Decision::Inconclusive;
}

struct Pooled {
    double se = 0.0;
    double df = 0.0;
};

/// Student's pooled standard error of x̄_A − x̄_B (Schuirmann's TOST): one seed-to-seed
/// variance s_p² = ((n_A − 1)s_A² + (n_B − 1)s_B²)/(n_A + n_B − 2) for both groups,
/// SE = s_p·√(1/n_A + 1/n_B), ν = n_A + n_B − 2. A group of one pack adds no variance
/// information, so a single candidate takes the reference's sd.
Pooled pooled(double var_a, std::size_t n_a, double var_b, std::size_t n_b) {
    const double na = static_cast<double>(n_a);
    const double nb = static_cast<double>(n_b);
    Pooled p;
    p.df = na + nb - 2.0;
    const double var = ((na - 1.0) * var_a + (nb - 1.0) * var_b) / p.df;
    p.se = std::sqrt(var * (1.0 / na + 1.0 / nb));
    return p;
}

/// The total-variation noise norm ½Σ|ε_k|, ε_k ~ N(0, v_k), taken as normal.
struct TvNoise {
    std::vector<double> variance;

    /// Its mean and variance, the variances scaled by `scale`.
    struct Law {
        double mean = 0.0;
        double var = 0.0;
    };

    [[nodiscard]] Law law(double scale) const {
        Law law;
        for (const double v : variance) {
            law.mean += 0.5 * std::sqrt(2.0 * v * scale / std::numbers::pi);
            law.var += 0.25 * v * scale * (1.0 - 2.0 / std::numbers::pi);
        }
        return law;
    }

    /// The (1 − p) quantile of the noise norm, the variances scaled by `scale`.
    [[nodiscard]] double quantile(double p, double scale) const {
        const Law l = law(scale);
        return l.var <= 0.0 ? l.mean
                            : l.mean + std::sqrt(l.var) *
                                           boost::math::quantile(boost::math::normal(), 1.0 - p);
    }

    /// P(noise norm ≥ x).
    [[nodiscard]] double survival(double x) const {
        if (x <= 0.0) {
            return 1.0;
        }
        const Law l = law(1.0);
        if (l.var <= 0.0) {
            return x > l.mean ? 0.0 : 1.0;
        }
        return boost::math::cdf(
            boost::math::complement(boost::math::normal(l.mean, std::sqrt(l.var)), x));
    }
};

}  // namespace

ScalarSample sample_of(const std::vector<double>& values) {
    return {values.empty() ? 0.0 : mean(values), sample_sd(values), values.size()};
}

EquivalenceResult test_scalar(const ScalarSample& candidate, const ScalarSample& reference,
                              double margin, double alpha) {
    const double estimate = candidate.mean - reference.mean;
    if (candidate.n == 0 || reference.n == 0 || (candidate.n < 2 && reference.n < 2)) {
        return undecidable(estimate, margin);
    }
    const double var_a = candidate.sd * candidate.sd;
    const double var_b = reference.sd * reference.sd;
    const Pooled w = pooled(var_a, candidate.n, var_b, reference.n);
    EquivalenceResult r;
    r.estimate = estimate;
    r.margin = margin;
    r.standard_error = w.se;
    r.degrees_of_freedom = w.df;
    const double t = t_quantile(1.0 - alpha, w.df);
    r.ci_low = estimate - t * w.se;
    r.ci_high = estimate + t * w.se;
    r.mdd = margin + (t + t_quantile(kPowerQuantile, w.df)) * w.se;
    r.zero_bound = t * w.se;
    const double excess = std::abs(estimate) - margin;
    if (w.se > 0.0) {
        r.p_differ = t_survival(excess / w.se, w.df);
        r.p_agree = t_survival(-excess / w.se, w.df);
    } else {
        r.p_differ = excess > 0.0 ? 0.0 : 1.0;
        r.p_agree = excess < 0.0 ? 0.0 : 1.0;
    }
    r.decision = decide(r.ci_low, r.ci_high, margin);
    if (r.decision == Decision::Inconclusive && excess != 0.0) {
        // t·SE falls as n grows: the smallest deciding n by bisection.
        const auto decides = [&](std::size_t n) {
            const Pooled wn = pooled(var_a, n, var_b, n);
            return t_quantile(1.0 - alpha, wn.df) * wn.se < std::abs(excess);
        };
        r.seeds_to_decide = detail::smallest_deciding(first_seeds_to_try(candidate.n, reference.n),
                                                      kMostSeeds, decides);
    }
    return r;
}

std::vector<double> noise_variance(const std::vector<std::vector<double>>& candidate,
                                   const std::vector<std::vector<double>>& reference) {
    std::size_t bins = 0;
    for (const auto* set : {&candidate, &reference}) {
        for (const auto& c : *set) {
            bins = std::max(bins, c.size());
        }
    }
    const auto per_bin_variance = [bins](const std::vector<std::vector<double>>& curves) {
        std::vector<double> var(bins, 0.0);
        if (curves.size() < 2) {
            return var;
        }
        for (std::size_t k = 0; k < bins; ++k) {
            std::vector<double> column;
            for (const auto& c : curves) {
                column.push_back(k < c.size() ? c[k] : 0.0);
            }
            const ScalarSample s = sample_of(column);
            var[k] = s.sd * s.sd;
        }
        return var;
    };
    const auto var_b = per_bin_variance(reference);
    const auto var_a = candidate.size() >= 2 ? per_bin_variance(candidate) : var_b;
    std::vector<double> v(bins, 0.0);
    for (std::size_t k = 0; k < bins; ++k) {
        v[k] = var_a[k] / static_cast<double>(candidate.size()) +
               var_b[k] / static_cast<double>(reference.size());
    }
    return v;
}

EquivalenceResult test_total_variation(double distance, const std::vector<double>& variance,
                                       double margin, std::size_t seeds_now, double alpha) {
    const TvNoise noise{variance};
    EquivalenceResult r;
    r.estimate = distance;
    r.margin = margin;
    const double q = noise.quantile(alpha, 1.0);
    r.standard_error = q / boost::math::quantile(boost::math::normal(), 1.0 - alpha);
    r.ci_low = std::max(0.0, distance - q);
    r.ci_high = distance + q;
    r.mdd = margin + q + noise.quantile(1.0 - kPowerQuantile, 1.0);
    r.zero_bound = q;
    r.p_differ = noise.survival(distance - margin);
    r.p_agree = noise.survival(margin - distance);
    r.decision = decide(r.ci_low, r.ci_high, margin);
    if (r.decision == Decision::Inconclusive) {
        // The variances shrink as 1/n with n seeds a side.
        for (std::size_t n = seeds_now + 1; n <= kMostSeeds; ++n) {
            const double scale = static_cast<double>(seeds_now) / static_cast<double>(n);
            if (noise.quantile(alpha, scale) < std::abs(distance - margin)) {
                r.seeds_to_decide = n;
                break;
            }
        }
    }
    return r;
}

}  // namespace sgmp::report
