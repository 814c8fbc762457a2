#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>

#include "equivalence_detail.hpp"
#include "sgmp/report/equivalence.hpp"
#include "sgmp/report/statistics.hpp"

namespace sgmp::report {

using detail::first_seeds_to_try;
using detail::kMostSeeds;
using detail::kPowerQuantile;
using detail::undecidable;

namespace {

/// Unbiased estimates of σ², σ⁴ and σ⁶ from a sample variance s² with f degrees of freedom
/// (s² ~ σ²χ²_f/f: E s⁴ = σ⁴(f + 2)/f, E s⁶ = σ⁶(f + 2)(f + 4)/f²).
struct Powers {
    double p2 = 0.0;
    double p4 = 0.0;
    double p6 = 0.0;
};

Powers powers_of(double s2, double f) {
    return {s2, s2 * s2 * f / (f + 2.0), s2 * s2 * s2 * f * f / ((f + 2.0) * (f + 4.0))};
}

/// One bin's estimates: the groups' variance powers and the mixed moments σ_A²σ_B², σ_A⁴σ_B²,
/// σ_A²σ_B⁴ (products of independent estimates, or powers of B's when A takes B's variance).
struct BinVariance {
    Powers a;
    Powers b;
    double ab22 = 0.0;
    double ab42 = 0.0;
    double ab24 = 0.0;
};

/// How the noise variance of a bin is made: v = ca·σ_A² + cb·σ_B², each variance estimated
/// with fa and fb degrees of freedom, or both from group B's one estimate (`shared`).
struct Design {
    double ca = 0.0;
    double cb = 0.0;
    double fa = 0.0;
    double fb = 0.0;
    bool shared = false;
};

/// The law of U = D̂² − t̂ (header) at ‖Δ‖ = θ: normal moments bounded over every direction of
/// Δ, quantiles by Cornish–Fisher.
struct L2Law {
    double w = 0.0;
    double t = 0.0;       // w Σ v̂_k
    double lambda = 0.0;  // max_k v̂_k
    double s2 = 0.0;      // w² Σ v_k²
    double s3 = 0.0;      // w³ Σ v_k³
    double vt = 0.0;      // w² Σ Var v̂_k = Var t̂
    double k3t = 0.0;     // w³ Σ κ₃ v̂_k = κ₃ t̂

    [[nodiscard]] double variance(double theta) const {
        return kL2DesignEffect * (4.0 * w * lambda * theta * theta + 2.0 * s2 + vt);
    }
    /// κ₃ U, bounded below (agree side) and above (differ side).
    [[nodiscard]] double third_low() const {
        return 8.0 * s3 - kL2DesignEffect * kL2DesignEffect * k3t;
    }
    [[nodiscard]] double third_high(double theta) const {
        return kL2DesignEffect * kL2DesignEffect *
                   (8.0 * s3 + 24.0 * w * w * lambda * lambda * theta * theta) -
               k3t;
    }
    /// The quantile of U at the normal quantile z, with third cumulant `third`.
    [[nodiscard]] double quantile(double theta, double z, double third) const {
        const double var = variance(theta);
        return theta * theta + std::sqrt(var) * z + (z * z - 1.0) * third / (6.0 * var);
    }
    [[nodiscard]] double low(double theta, double z) const {
        return quantile(theta, -z, third_low());
    }
    [[nodiscard]] double high(double theta, double z) const {
        return quantile(theta, z, third_high(theta));
    }
};

L2Law law_of(const std::vector<BinVariance>& bins, const Design& d, double w) {
    L2Law law;
    law.w = w;
    double t = 0.0;
    double s2 = 0.0;
    double s3 = 0.0;
    double vt = 0.0;
    double k3t = 0.0;
    const double ca = d.ca;
    const double cb = d.cb;
    for (const BinVariance& b : bins) {
        const double v = ca * b.a.p2 + cb * b.b.p2;
        t += v;
        law.lambda = std::max(law.lambda, v);
        s2 += ca * ca * b.a.p4 + 2.0 * ca * cb * b.ab22 + cb * cb * b.b.p4;
        s3 += ca * ca * ca * b.a.p6 + 3.0 * ca * ca * cb * b.ab42 + 3.0 * ca * cb * cb * b.ab24 +
              cb * cb * cb * b.b.p6;
        if (d.shared) {
            const double c = ca + cb;
            vt += 2.0 * c * c * b.b.p4 / d.fb;
            k3t += 8.0 * c * c * c * b.b.p6 / (d.fb * d.fb);
        } else {
            vt += 2.0 * ca * ca * b.a.p4 / d.fa + 2.0 * cb * cb * b.b.p4 / d.fb;
            k3t += 8.0 * ca * ca * ca * b.a.p6 / (d.fa * d.fa) +
                   8.0 * cb * cb * cb * b.b.p6 / (d.fb * d.fb);
        }
    }
    law.t = w * t;
    law.s2 = w * w * s2;
    law.s3 = w * w * w * s3;
    law.vt = w * w * vt;
    law.k3t = w * w * w * k3t;
    return law;
}

constexpr int kGridPoints = 64;
constexpr int kBisections = 100;

/// A θ ≥ `start` with f(θ) > u (f grows as θ² for large θ).
template <class F>
double above(const F& f, double u, double start) {
    double top = std::max(start, 1e-300);
    for (int i = 0; i < 2000 && f(top) <= u; ++i) {
        top *= 2.0;
    }
    return top;
}

/// Bisection of f(θ) = u on [lo, hi] with f(lo) ≤ u < f(hi).
template <class F>
double bisect(const F& f, double u, double lo, double hi) {
    for (int i = 0; i < kBisections && hi - lo > 1e-15 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) <= u ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

/// The largest θ ≥ 0 with f(θ) ≤ u, 0 when there is none (f continuous, growing for large θ).
template <class F>
double largest_at_most(const F& f, double u, double start) {
    const double top = above(f, u, start);
    for (int i = kGridPoints - 1; i >= 0; --i) {
        const double theta = top * i / kGridPoints;
        if (f(theta) <= u) {
            return bisect(f, u, theta, top * (i + 1) / kGridPoints);
        }
    }
    return 0.0;
}

/// The smallest θ ≥ 0 with f(θ) ≥ u (0 when f(0) ≥ u).
template <class F>
double smallest_at_least(const F& f, double u, double start) {
    if (f(0.0) >= u) {
        return 0.0;
    }
    const double top = above(f, u, start);
    for (int i = 1; i <= kGridPoints; ++i) {
        const double theta = top * i / kGridPoints;
        if (f(theta) >= u) {  // f < u at the grid point before: bisect between them
            double a = top * (i - 1) / kGridPoints;
            double b = theta;
            for (int k = 0; k < kBisections && b - a > 1e-15 * b; ++k) {
                const double mid = 0.5 * (a + b);
                (f(mid) < u ? a : b) = mid;
            }
            return 0.5 * (a + b);
        }
    }
    return top;
}

/// Φ⁻¹ of a Cornish–Fisher quantile: the z with x = z + g(z² − 1), g = γ/6 (on the branch
/// through z = x at g = 0; the vertex −1/(2g) when x lies beyond it).
double cornish_fisher_z(double x, double g) {
    const double disc = 1.0 + 4.0 * g * (x + g);
    if (disc < 0.0) {
        return -0.5 / g;
    }
    return 2.0 * (x + g) / (1.0 + std::sqrt(disc));
}

struct L2Bounds {
    double low = 0.0;
    double high = 0.0;
};

L2Bounds bounds_of(const L2Law& law, double u, double margin, double z) {
    const double start = std::max(margin, std::sqrt(std::max(u, 0.0)));
    return {smallest_at_least([&](double th) { return law.high(th, z); }, u, start),
            largest_at_most([&](double th) { return law.low(th, z); }, u, start)};
}

}  // namespace

namespace {

/// The groups' per-bin estimates (group B lends its variance to a group A of one pack).
struct L2Setup {
    std::vector<BinVariance> variance;
    double distance = 0.0;
    double na = 0.0;
    double nb = 0.0;
    bool shared = false;
    bool swap = false;
    bool valid = false;  // group B has ≥ 2 curves and group A ≥ 1
};

L2Setup setup_of(const std::vector<std::vector<double>>& candidate,
                 const std::vector<std::vector<double>>& reference, double bin_width) {
    L2Setup out;
    // A group of one pack takes the other's variance: B is the group that lends it.
    out.swap = reference.size() < 2 && candidate.size() >= 2;
    const auto& ga = out.swap ? reference : candidate;
    const auto& gb = out.swap ? candidate : reference;
    std::size_t bins = 0;
    for (const auto* set : {&ga, &gb}) {
        for (const auto& c : *set) {
            bins = std::max(bins, c.size());
        }
    }
    const auto column_stats = [bins](const std::vector<std::vector<double>>& curves) {
        std::vector<ScalarSample> s(bins);
        for (std::size_t k = 0; k < bins; ++k) {
            std::vector<double> column;
            for (const auto& c : curves) {
                column.push_back(k < c.size() ? c[k] : 0.0);
            }
            s[k] = sample_of(column);
        }
        return s;
    };
    const auto sa = column_stats(ga);
    const auto sb = column_stats(gb);
    double d2 = 0.0;
    for (std::size_t k = 0; k < bins; ++k) {
        d2 += (sa[k].mean - sb[k].mean) * (sa[k].mean - sb[k].mean);
    }
    out.distance = std::sqrt(d2 * bin_width);
    if (gb.size() < 2 || ga.empty()) {
        return out;
    }
    out.valid = true;
    out.na = static_cast<double>(ga.size());
    out.nb = static_cast<double>(gb.size());
    out.shared = ga.size() < 2;
    out.variance.resize(bins);
    for (std::size_t k = 0; k < bins; ++k) {
        BinVariance& v = out.variance[k];
        v.b = powers_of(sb[k].sd * sb[k].sd, out.nb - 1.0);
        if (out.shared) {
            v.a = v.b;
            v.ab22 = v.b.p4;
            v.ab42 = v.ab24 = v.b.p6;
        } else {
            v.a = powers_of(sa[k].sd * sa[k].sd, out.na - 1.0);
            v.ab22 = v.a.p2 * v.b.p2;
            v.ab42 = v.a.p4 * v.b.p2;
            v.ab24 = v.a.p2 * v.b.p4;
        }
    }
    return out;
}

}  // namespace

EquivalenceResult test_l2_curves(const std::vector<std::vector<double>>& candidate,
                                 const std::vector<std::vector<double>>& reference,
                                 double bin_width, double margin, double alpha) {
    const L2Setup setup = setup_of(candidate, reference, bin_width);
    const double distance = setup.distance;
    if (!setup.valid) {
        return undecidable(distance, margin);
    }
    const auto& variance = setup.variance;
    const double na = setup.na;
    const double nb = setup.nb;
    const bool shared = setup.shared;
    const std::size_t size_a = static_cast<std::size_t>(na);
    const std::size_t size_b = static_cast<std::size_t>(nb);
    const L2Law law = law_of(variance, {1.0 / na, 1.0 / nb, na - 1.0, nb - 1.0, shared}, bin_width);
    const double u = distance * distance - law.t;
    const double z = boost::math::quantile(boost::math::normal(), 1.0 - alpha);
    const double m2 = margin * margin;

    EquivalenceResult r;
    r.estimate = distance;
    r.margin = margin;
    const double var_m = law.variance(margin);
    r.standard_error =
        margin > 0.0 ? std::sqrt(var_m) / (2.0 * margin) : std::numeric_limits<double>::infinity();
    r.degrees_of_freedom =
        law.vt > 0.0 ? 2.0 * law.t * law.t / law.vt : std::numeric_limits<double>::infinity();
    if (var_m <= 0.0) {  // no scatter in either group: U is the exact squared distance
        r.ci_low = r.ci_high = distance;
        r.p_agree = distance < margin ? 0.0 : 1.0;
        r.p_differ = distance > margin ? 0.0 : 1.0;
        r.mdd = margin;
        r.zero_bound = 0.0;
        r.decision = distance < margin
                         ? Decision::Agree
                         : (distance > margin ? Decision::Differ : Decision::Inconclusive);
        return r;
    }
    const L2Bounds b = bounds_of(law, u, margin, z);
    r.ci_low = b.low;
    r.ci_high = b.high;
    r.zero_bound = bounds_of(law, 0.0, margin, z).high;
    const double sd_m = std::sqrt(var_m);
    const double x = (u - m2) / sd_m;
    const boost::math::normal unit;
    r.p_agree = boost::math::cdf(unit, cornish_fisher_z(x, law.third_low() / (6.0 * var_m * sd_m)));
    r.p_differ = boost::math::cdf(boost::math::complement(
        unit, cornish_fisher_z(x, law.third_high(margin) / (6.0 * var_m * sd_m))));
    // mdd: the θ whose U reaches the differ threshold q₀.₉₅(m) with probability 80 %.
    const double z80 = boost::math::quantile(unit, kPowerQuantile);
    const double threshold = law.high(margin, z);
    r.mdd = smallest_at_least([&](double th) { return law.low(th, z80); }, threshold, margin);
    r.decision = r.ci_high < margin
                     ? Decision::Agree
                     : (r.ci_low > margin ? Decision::Differ : Decision::Inconclusive);
    if (r.decision == Decision::Inconclusive) {
        // n seeds a side, each group with its own variance at n − 1 degrees of freedom; the
        // bounds narrow as n grows, so the smallest deciding n is found by bisection.
        const auto decided = [&](std::size_t n) {
            const double c = 1.0 / static_cast<double>(n);
            const double f = static_cast<double>(n) - 1.0;
            const L2Bounds bn =
                bounds_of(law_of(variance, {c, c, f, f, false}, bin_width), u, margin, z);
            return bn.high < margin || bn.low > margin;
        };
        r.seeds_to_decide =
            detail::smallest_deciding(first_seeds_to_try(size_a, size_b), kMostSeeds, decided);
    }
    return r;
}

bool l2_decides_with(const std::vector<std::vector<double>>& candidate,
                     const std::vector<std::vector<double>>& reference, double bin_width,
                     double margin, double alpha, std::size_t candidate_n,
                     std::size_t reference_n) {
    const L2Setup setup = setup_of(candidate, reference, bin_width);
    if (!setup.valid || candidate_n < 2 || reference_n < 2) {
        return false;
    }
    const L2Law now = law_of(
        setup.variance,
        {1.0 / setup.na, 1.0 / setup.nb, setup.na - 1.0, setup.nb - 1.0, setup.shared}, bin_width);
    const double u = setup.distance * setup.distance - now.t;  // the same estimate of θ²
    const double n_a = static_cast<double>(setup.swap ? reference_n : candidate_n);
    const double n_b = static_cast<double>(setup.swap ? candidate_n : reference_n);
    const L2Law law =
        law_of(setup.variance, {1.0 / n_a, 1.0 / n_b, n_a - 1.0, n_b - 1.0, false}, bin_width);
    if (law.variance(margin) <= 0.0) {
        return setup.distance != margin;
    }
    const double z = boost::math::quantile(boost::math::normal(), 1.0 - alpha);
    const L2Bounds b = bounds_of(law, u, margin, z);
    return b.high < margin || b.low > margin;
}

}  // namespace sgmp::report
