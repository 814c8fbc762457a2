// The physical checks of a pack's summary and the equilibrium it claims (agreement.hpp:
// check_physical, uncertified_reason).
#include <cmath>
#include <stdexcept>
#include <string>

#include "sgmp/metrics/coordination_tolerances.hpp"
#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/report/agreement.hpp"

namespace sgmp::report {

using metrics::coordination_tolerance_names;
using metrics::coordination_tolerances;

namespace {

/// Kepler's bound, the densest packing of equal spheres: π/√18.
constexpr double kKeplerBound = 0.74048;

bool of_several_sizes(const PackSummary& pack) {
    for (const auto& [key, value] : pack.provenance) {
        if (key == "size_modes") {
            return value.find(',') != std::string::npos;
        }
    }
    return false;
}

[[noreturn]] void impossible(const PackSummary& pack, const std::string& what,
                             const std::string& rule) {
    throw std::invalid_argument(pack.source + ": " + what + " is physically impossible (" + rule +
                                ")");
}

/// The largest mean coordination Z(δ) a pack can have, δ the gap tolerance in units of
/// the mean diameter d. One size: 12, the kissing number, for δ ≤ 2·10⁻² (a 13th neighbour
/// needs a shell out to 1.0454·d, Tammes' problem for 13 points: more than 1 + δ even with
/// overlaps of 2 % of d); beyond, the cap-area bound 2/(1 − cos θ), sin θ = 1/(2(1 + δ))
/// (16 at δ = 5·10⁻²). Several sizes: twice that, 24 at contact, a generous bound: Z counts
/// each contact twice, and at its smaller sphere a contact is one of at most 12 with
/// spheres at least as large (shrunk to its size, they still do not overlap).
double coordination_bound(double delta, bool several_sizes) {
    constexpr double kKissingNumber = 12.0;
    constexpr double kTammesShell = 0.02;  // the largest δ of the reported ones below 0.0454
    const double sin_theta = 1.0 / (2.0 * (1.0 + delta));
    const double one_size = delta <= kTammesShell
                                ? kKissingNumber
                                : std::floor(2.0 / (1.0 - std::sqrt(1.0 - sin_theta * sin_theta)));
    return several_sizes ? 2.0 * one_size : one_size;
}

/// Refuses a mean coordination `value` at tolerance index `t` outside [0, the bound].
void check_coordination(const PackSummary& pack, std::size_t t, double value) {
    const std::string what = metrics::coordination_metric(t).name + " = " + std::to_string(value);
    if (!std::isfinite(value) || value < 0.0) {
        impossible(pack, what, "must be finite and >= 0");
    }
    const bool several = of_several_sizes(pack);
    const double bound = coordination_bound(coordination_tolerances().at(t), several);
    if (value > bound) {
        impossible(pack, what,
                   std::string(several ? "spheres of several sizes" : "a sphere of one size") +
                       " averages at most " + format_number(bound) + " contacts at this tolerance");
    }
}

}  // namespace

std::string uncertified_reason(const PackSummary& pack) {
    std::string relax;
    std::string certified;
    std::string residual;
    for (const auto& [key, value] : pack.provenance) {
        relax = key == "relax" ? value : relax;
        certified = key == "certified" ? value : certified;
        residual = key == "certificate_residual_max" ? value : residual;
    }
    if (relax.empty() || relax == "none" || certified == "true") {
        return "";
    }
    if (certified.empty()) {
        return "relaxed without an equilibrium certificate";
    }
    if (residual.empty()) {
        return "no equilibrium certificate for --relax " + relax;
    }
    char text[64];
    std::snprintf(text, sizeof text, "largest residual %.3g m·g",
                  std::strtod(residual.c_str(), nullptr));
    return text;
}

void check_physical(const PackSummary& pack) {
    const auto& names = coordination_tolerance_names();
    for (const auto& rule : metric_rules()) {
        if (rule.kind != MetricKind::Scalar) {
            continue;
        }
        const double v = pack.scalar(rule.name);
        if (std::isnan(v)) {
            continue;  // not measured (a batch summary row): not judged
        }
        const std::string what = rule.name + " = " + std::to_string(v);
        if (!std::isfinite(v) || v < 0.0) {
            impossible(pack, what, "must be finite and >= 0");
        }
        const metrics::PhysicalBound bound = rule.descriptor->bound;
        if (bound == metrics::PhysicalBound::Coordination) {
            check_coordination(pack, rule.descriptor->tolerance, v);
        }
        if (bound == metrics::PhysicalBound::PackingFraction) {
            if (of_several_sizes(pack) ? v >= 1.0 : v > kKeplerBound) {
                impossible(
                    pack, what,
                    of_several_sizes(pack) ? "must be < 1" : "one size packs to at most 0.74048");
            }
        }
    }
    for (std::size_t t = 0; t < pack.z_mean.size() && t < names.size(); ++t) {
        check_coordination(pack, t, pack.z_mean[t]);
    }
    // A slab's φ(y) may pass Kepler's bound (a slab one d thick centred on a dense layer of
    // a crystal), never 1.
    for (const double phi : pack.phi_y) {
        if (!(phi >= 0.0 && phi <= 1.0)) {
            impossible(pack, "phi(y) = " + format_number(phi), "must lie in [0, 1]");
        }
    }
    for (const auto* positions : {&pack.phi_y_mid, &pack.gr_r}) {
        for (const double x : *positions) {
            if (!std::isfinite(x)) {
                impossible(pack, (positions == &pack.gr_r ? "r/d = " : "y = ") + format_number(x),
                           "a position must be finite");
            }
        }
    }
    for (const double g : pack.gr) {
        if (!(g >= 0.0) || !std::isfinite(g)) {
            impossible(pack, "g(r) = " + std::to_string(g), "must be finite and >= 0");
        }
    }
    for (std::size_t t = 0; t < pack.p_z.size(); ++t) {
        double sum = 0.0;
        for (const double q : pack.p_z[t]) {
            if (!(q >= 0.0 && q <= 1.0)) {
                impossible(pack, "P(Z) at " + names.at(t) + " = " + std::to_string(q),
                           "must lie in [0, 1]");
            }
            sum += q;
        }
        if (!pack.p_z[t].empty() && std::abs(sum - 1.0) > 1e-6) {
            impossible(pack, "P(Z) at " + names.at(t) + " sums to " + std::to_string(sum),
                       "must sum to 1");
        }
    }
}

}  // namespace sgmp::report
