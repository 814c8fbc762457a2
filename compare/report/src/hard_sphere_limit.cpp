#include "sgmp/compare/hard_sphere_limit.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace sgmp::compare {
namespace {

std::optional<std::string> provenance_value(const PackSummary& pack, const std::string& key) {
    for (const auto& [k, v] : pack.provenance) {
        if (k == key) {
            return v;
        }
    }
    return std::nullopt;
}

double youngs_modulus(const PackSummary& pack) {
    const auto text = provenance_value(pack, kYoungsModulusKey);
    if (!text) {
        throw std::invalid_argument(pack.source + ": no " + std::string(kYoungsModulusKey) +
                                    " key, so its hard-sphere limit is undefined");
    }
    double value = 0.0;
    const char* end = text->data() + text->size();
    const auto [at, error] = std::from_chars(text->data(), end, value);
    if (error != std::errc() || at != end) {
        throw std::invalid_argument(pack.source + ": " + std::string(kYoungsModulusKey) + " '" +
                                    *text + "' is not a number");
    }
    return value;
}

/// The overlap metrics: zero between hard spheres, whatever the pours' overlaps.
bool is_overlap_metric(const std::string& name) {
    return name.find("overlap") != std::string::npos;
}

/// stiff + a·(stiff − soft), value by value; a value one side lacks counts as 0 (a P(Z) bin
/// beyond that pack's largest Z).
std::vector<double> extrapolate(const std::vector<double>& soft, const std::vector<double>& stiff,
                                double a) {
    std::vector<double> out(std::max(soft.size(), stiff.size()), 0.0);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double s = i < soft.size() ? soft[i] : 0.0;
        const double h = i < stiff.size() ? stiff[i] : 0.0;
        out[i] = h + a * (h - s);
    }
    return out;
}

/// The pack's `seed` key, or "" when it has none.
std::string seed_of(const PackSummary& pack) {
    return provenance_value(pack, "seed").value_or("");
}

constexpr std::string_view kLimitSuffix = " hard-sphere limit";

}  // namespace

std::string hard_sphere_limit_label(const std::string& class_label) {
    return class_label + std::string(kLimitSuffix);
}

std::optional<std::string> class_of_hard_sphere_limit(const std::string& label) {
    if (!label.ends_with(kLimitSuffix)) {
        return std::nullopt;
    }
    return label.substr(0, label.size() - kLimitSuffix.size());
}

double hard_sphere_coefficient(double youngs_soft, double youngs_stiff) {
    if (!(youngs_soft > 0.0) || !(youngs_stiff > youngs_soft)) {
        throw std::invalid_argument("a hard-sphere limit needs E_stiff > E_soft > 0, got " +
                                    std::to_string(youngs_soft) + " and " +
                                    std::to_string(youngs_stiff) + " Pa");
    }
    return 1.0 / (std::cbrt(youngs_stiff / youngs_soft) - 1.0);
}

PackSummary hard_sphere_limit(const PackSummary& soft, const PackSummary& stiff) {
    if (soft.count != stiff.count) {
        throw std::invalid_argument(stiff.source + " holds " + std::to_string(stiff.count) +
                                    " particles, " + soft.source + " " +
                                    std::to_string(soft.count));
    }
    if (soft.gr_r != stiff.gr_r) {
        throw std::invalid_argument(soft.source + " and " + stiff.source +
                                    " use different g(r) bins");
    }
    const double a = hard_sphere_coefficient(youngs_modulus(soft), youngs_modulus(stiff));
    PackSummary h = stiff;
    h.source = "hard-sphere limit of " + soft.source + " and " + stiff.source;
    h.provenance = {{"seed", seed_of(stiff)},
                    {"hard_sphere_limit_coefficient", std::to_string(a)},
                    {"soft", soft.source},
                    {"stiff", stiff.source}};
    const auto& rules = metric_rules();
    std::size_t k = 0;
    for (const auto& rule : rules) {
        if (rule.kind != MetricKind::Scalar) {
            continue;
        }
        h.scalars[k] = is_overlap_metric(rule.name)
                           ? 0.0
                           : stiff.scalars[k] + a * (stiff.scalars[k] - soft.scalars[k]);
        ++k;
    }
    h.gr = extrapolate(soft.gr, stiff.gr, a);
    h.z_mean = extrapolate(soft.z_mean, stiff.z_mean, a);
    for (std::size_t t = 0; t < h.p_z.size(); ++t) {
        h.p_z[t] =
            extrapolate(t < soft.p_z.size() ? soft.p_z[t] : std::vector<double>{}, stiff.p_z[t], a);
    }
    return h;
}

Group hard_sphere_limit(const Group& soft, const Group& stiff, const std::string& label,
                        std::vector<std::string>& unpaired) {
    std::map<std::pair<std::size_t, std::string>, const PackSummary*> soft_of;
    for (const auto& pack : soft.packs) {
        soft_of[{pack.count, seed_of(pack)}] = &pack;
    }
    Group limit{label, {}};
    for (const auto& pack : stiff.packs) {
        const auto key = std::pair{pack.count, seed_of(pack)};
        const auto partner = soft_of.find(key);
        if (partner == soft_of.end() || key.second.empty()) {
            unpaired.push_back(pack.source + " (" + stiff.label + ") has no pour of " + soft.label +
                               " with its count and seed: left out of " + label);
            continue;
        }
        limit.packs.push_back(hard_sphere_limit(*partner->second, pack));
    }
    return limit;
}

}  // namespace sgmp::compare
