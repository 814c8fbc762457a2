#include "sgmp/report/group_sequential.hpp"

#include "sgmp/pack/random.hpp"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <set>
#include <stdexcept>

namespace sgmp::report {
namespace {

/// Paths of the Student boundaries' simulation: the spent α's binomial sd is
/// √(0.05·0.95/200000) = 4.9·10⁻⁴ at 5 %; fewer (down to 20,000, sd 1.5·10⁻³) when the
/// design draws more than 2·10⁸ normals (n_B + N above 1000).
constexpr std::size_t kStudentPaths = 200000;
constexpr std::size_t kLeastStudentPaths = 20000;
constexpr double kMostStudentDraws = 2e8;
constexpr std::uint64_t kStudentSeed = 20261207;
/// The level of a look that spends nothing (a boundary beyond every path).
constexpr double kSmallestLevel = 1e-12;

double normal_cdf(double x) {
    return 0.5 * std::erfc(-x / std::numbers::sqrt2);
}

double normal_upper(double x) {
    return 0.5 * std::erfc(x / std::numbers::sqrt2);
}

/// Φ⁻¹(p) by bisection on the CDF (p in (0, 1); the few calls need no speed).
double normal_quantile(double p) {
    double lo = -40.0;
    double hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (normal_cdf(mid) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

/// Most cells of the grid (the cell widens to keep to it).
constexpr std::size_t kMostCells = 12000;

/// The sub-probability of the score S_k = Z_k·√I_k on the continuation region, as a
/// histogram on a fixed grid (mass uniform within a cell). S is a Gaussian random walk with
/// independent increments N(0, I_k − I_{k−1}) under H0, so one grid serves every look.
struct Histogram {
    double low = 0.0;
    double width = 0.0;
    std::vector<double> mass;

    [[nodiscard]] double edge(std::size_t i) const { return low + static_cast<double>(i) * width; }
};

/// The kernel of an increment of variance v on cells of width h, with variance exactly v:
/// the normal's cell masses at sd √(v − h²/12) (Sheppard's correction) when v ≥ h²/6, else
/// the three-point kernel {v/2h², 1 − v/h², v/2h²}.
std::vector<double> kernel_of(double v, double h, std::size_t& half) {
    if (v < h * h / 6.0) {
        half = 1;
        const double side = v / (2.0 * h * h);
        return {side, 1.0 - 2.0 * side, side};
    }
    const double sd = std::sqrt(v - h * h / 12.0);
    half = static_cast<std::size_t>(std::ceil(9.0 * sd / h));
    std::vector<double> k(2 * half + 1);
    for (std::size_t j = 0; j < k.size(); ++j) {
        const double centre = (static_cast<double>(j) - static_cast<double>(half)) * h;
        k[j] = normal_cdf((centre + 0.5 * h) / sd) - normal_cdf((centre - 0.5 * h) / sd);
    }
    return k;
}

/// The histogram after an increment of variance v (mass leaving the grid is dropped: the
/// grid spans −8.5 to +12 sd of the last look).
void step(Histogram& hist, double v) {
    std::size_t half = 0;
    const auto k = kernel_of(v, hist.width, half);
    std::vector<double> next(hist.mass.size(), 0.0);
    const auto cells = static_cast<std::ptrdiff_t>(hist.mass.size());
    const auto reach = static_cast<std::ptrdiff_t>(half);
    for (std::ptrdiff_t i = 0; i < cells; ++i) {
        const double m = hist.mass[static_cast<std::size_t>(i)];
        if (m == 0.0) {
            continue;
        }
        const std::ptrdiff_t from = std::max<std::ptrdiff_t>(0, i - reach);
        const std::ptrdiff_t to = std::min<std::ptrdiff_t>(cells - 1, i + reach);
        for (std::ptrdiff_t j = from; j <= to; ++j) {
            next[static_cast<std::size_t>(j)] += m * k[static_cast<std::size_t>(j - i + reach)];
        }
    }
    hist.mass = std::move(next);
}

/// The b with mass above b = `increment` (mass uniform in each cell), and the histogram cut
/// there; the grid's top when even all of it is less.
double cut_at(Histogram& hist, double increment) {
    double above = 0.0;
    for (std::size_t i = hist.mass.size(); i-- > 0;) {
        const double m = hist.mass[i];
        if (above + m >= increment && m > 0.0) {
            const double share = (increment - above) / m;  // of this cell, from its top
            const double b = hist.edge(i + 1) - share * hist.width;
            hist.mass[i] = m * (1.0 - share);
            return b;
        }
        above += m;
        hist.mass[i] = 0.0;
    }
    return hist.edge(0);
}

/// A standard normal draw from sgmp::Random (Box–Muller, the cosine branch).
double normal_draw(Random& random) {
    const double u = 1.0 - random.uniform01();  // (0, 1]
    const double v = random.uniform01();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

/// One simulated path of the pooled Student statistic: Welford sums of both groups.
struct Path {
    double mean_a = 0.0;
    double ss_a = 0.0;
    double n_a = 0.0;
    double mean_b = 0.0;
    double ss_b = 0.0;
    bool crossed = false;
};

void add_draw(double x, double& mean, double& ss, double& n) {
    n += 1.0;
    const double d = x - mean;
    mean += d / n;
    ss += d * (x - mean);
}

/// T = (x̄_A − x̄_B)/(s_p √(1/n_A + 1/n_B)) of a path (−∞ without degrees of freedom).
double student_t(const Path& p, double n_b) {
    const double df = p.n_a + n_b - 2.0;
    if (df <= 0.0) {
        return -std::numeric_limits<double>::infinity();
    }
    const double se = std::sqrt((p.ss_a + p.ss_b) / df * (1.0 / p.n_a + 1.0 / n_b));
    return se > 0.0 ? (p.mean_a - p.mean_b) / se : -std::numeric_limits<double>::infinity();
}

/// The boundaries of the pooled Student statistics T_k (whose joint law under H0 is free of
/// σ and of the mean: one simulation serves every metric) that spend `spent` (cumulative),
/// as nominal one-sided levels of the t test at each look's ν = n_k + n_B − 2.
std::vector<double> student_levels(const std::vector<std::size_t>& candidate_n,
                                   std::size_t reference_n, const std::vector<double>& spent) {
    Random random(kStudentSeed);
    const double draws = static_cast<double>(reference_n + candidate_n.back());
    const auto count = std::clamp<std::size_t>(static_cast<std::size_t>(kMostStudentDraws / draws),
                                               kLeastStudentPaths, kStudentPaths);
    std::vector<Path> paths(count);
    const double n_b = static_cast<double>(reference_n);
    for (Path& p : paths) {
        double n = 0.0;
        for (std::size_t i = 0; i < reference_n; ++i) {
            add_draw(normal_draw(random), p.mean_b, p.ss_b, n);
        }
    }
    std::vector<double> levels;
    std::size_t crossed = 0;
    std::vector<double> alive;
    for (std::size_t k = 0; k < candidate_n.size(); ++k) {
        alive.clear();
        for (Path& p : paths) {
            while (p.n_a < static_cast<double>(candidate_n[k])) {
                add_draw(normal_draw(random), p.mean_a, p.ss_a, p.n_a);
            }
            if (!p.crossed) {
                alive.push_back(student_t(p, n_b));
            }
        }
        const auto target = static_cast<std::size_t>(std::llround(spent[k] * double(count)));
        const std::size_t need = target > crossed ? target - crossed : 0;
        double c = std::numeric_limits<double>::infinity();
        if (need > 0 && need < alive.size()) {
            std::nth_element(alive.begin(), alive.begin() + long(need), alive.end(),
                             std::greater<>());
            const double above = *std::min_element(alive.begin(), alive.begin() + long(need));
            c = 0.5 * (above + alive[need]);
        }
        for (Path& p : paths) {
            if (!p.crossed && student_t(p, n_b) > c) {
                p.crossed = true;
                ++crossed;
            }
        }
        const double df = static_cast<double>(candidate_n[k] + reference_n) - 2.0;
        if (k == 0) {  // T₁ alone is Student's t_ν: its level is the spent α itself
            levels.push_back(std::max(spent[0], kSmallestLevel));
            continue;
        }
        levels.push_back(std::isfinite(c) && df > 0.0 ? boost::math::cdf(boost::math::complement(
                                                            boost::math::students_t(df), c))
                                                      : kSmallestLevel);
    }
    return levels;
}

}  // namespace

double spent_alpha(double t, double alpha) {
    if (t <= 0.0) {
        return 0.0;
    }
    const double z = normal_quantile(1.0 - alpha / 2.0);
    return std::min(alpha, 2.0 * normal_upper(z / std::sqrt(std::min(t, 1.0))));
}

double information(std::size_t candidate_n, std::size_t reference_n) {
    return 1.0 / (1.0 / static_cast<double>(candidate_n) + 1.0 / static_cast<double>(reference_n));
}

std::vector<std::size_t> look_schedule(const SequentialDesign& design, std::size_t available) {
    const std::size_t last = std::max(design.max_seeds, available);
    const std::size_t block = std::max<std::size_t>(1, design.block);
    std::set<std::size_t> looks{last};
    for (std::size_t n = std::max<std::size_t>(1, std::min(design.first_look, last)); n < last;
         n += block) {
        looks.insert(n);
    }
    if (available > 0) {
        looks.insert(available);  // an unplanned look when it is off the grid
    }
    return {looks.begin(), looks.end()};
}

std::vector<Look> boundaries(const std::vector<std::size_t>& candidate_n, std::size_t reference_n,
                             double alpha) {
    if (candidate_n.empty() || reference_n == 0 || candidate_n.front() == 0 ||
        !std::is_sorted(candidate_n.begin(), candidate_n.end(), std::less_equal<>())) {
        throw std::invalid_argument("looks must be positive, increasing seed counts");
    }
    const double total = information(candidate_n.back(), reference_n);
    const double first = information(candidate_n.front(), reference_n);
    Histogram hist;
    hist.low = kBoundaryFloor * std::sqrt(total);
    const double top = kBoundaryCeiling * std::sqrt(total);
    hist.width = std::max(kBoundaryCell * std::sqrt(first),
                          (top - hist.low) / static_cast<double>(kMostCells));
    hist.mass.assign(static_cast<std::size_t>(std::ceil((top - hist.low) / hist.width)), 0.0);
    for (std::size_t i = 0; i < hist.mass.size(); ++i) {  // S₁ ~ N(0, I₁)
        hist.mass[i] = normal_cdf(hist.edge(i + 1) / std::sqrt(first)) -
                       normal_cdf(hist.edge(i) / std::sqrt(first));
    }
    std::vector<Look> looks;
    double spent_before = 0.0;
    double info_before = first;
    for (const std::size_t n : candidate_n) {
        Look look;
        look.candidate_n = n;
        const double info = information(n, reference_n);
        look.fraction = info / total;
        look.alpha_spent = spent_alpha(look.fraction, alpha);
        if (!looks.empty()) {
            step(hist, info - info_before);
        }
        const double b = cut_at(hist, std::max(0.0, look.alpha_spent - spent_before));
        look.boundary = std::clamp(b / std::sqrt(info), -kBoundaryCeiling, kBoundaryCeiling);
        if (looks.empty()) {  // exact at the first look
            look.boundary = std::min(kBoundaryCeiling, normal_quantile(1.0 - look.alpha_spent));
        }
        look.nominal_alpha = normal_upper(look.boundary);
        spent_before = look.alpha_spent;
        info_before = info;
        looks.push_back(look);
    }
    std::vector<double> spent;
    for (const Look& l : looks) {
        spent.push_back(l.alpha_spent);
    }
    const auto levels = student_levels(candidate_n, reference_n, spent);
    for (std::size_t k = 0; k < looks.size(); ++k) {
        looks[k].student_alpha = levels[k];
    }
    return looks;
}

std::vector<Look> BoundaryCache::get(const std::vector<std::size_t>& candidate_n,
                                     std::size_t reference_n, double alpha) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto key = std::make_tuple(candidate_n, reference_n, alpha);
    auto found = cache_.find(key);
    if (found == cache_.end()) {
        found = cache_.emplace(key, boundaries(candidate_n, reference_n, alpha)).first;
    }
    return found->second;
}

}  // namespace sgmp::report
