#include "sgmp/reference/pour_params.hpp"

#include "sgmp/reference/launcher.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/random.hpp"

namespace sgmp::reference {
namespace {

/// Throws ParameterError(name, value, "must be " + rule) unless `ok` and value is finite.
void require(bool ok, const char* name, double value, const std::string& rule) {
    if (!ok || !std::isfinite(value)) {  // inf passed "positive" and "above" rules
        throw ParameterError(name, format_number(value), "must be " + rule);
    }
}

}  // namespace

void PourParams::validate() const {
    require(count >= 1 && count <= kMaxCount, "count", static_cast<double>(count),
            "between 1 and " + std::to_string(kMaxCount));
    require(phi_target > 0.0 && phi_target <= kMaxPhiTarget, "phi_target", phi_target,
            "in (0, 0.74048]");
    require(friction >= 0.0 && friction <= 10.0, "friction", friction, "in [0, 10]");
    require(restitution > 0.0 && restitution < 1.0, "restitution", restitution, "in (0, 1)");
    require(rolling_friction >= 0.0 && rolling_friction <= 1.0, "rolling_friction",
            rolling_friction, "in [0, 1]");
    // LIGGGHTS refuses softer materials in SI units.
    require(youngs_modulus > 5e6, "youngs_modulus", youngs_modulus, "above 5e6 Pa");
    require(poisson_ratio > 0.0 && poisson_ratio < 0.5, "poisson_ratio", poisson_ratio,
            "in (0, 0.5)");
    require(density > 0.0, "density", density, "positive");
    require(gravity > 0.0, "gravity", gravity, "positive");
    require(timestep_fraction > 0.0 && timestep_fraction <= 0.5, "timestep_fraction",
            timestep_fraction, "in (0, 0.5]");
    require(settle_threshold > 0.0, "settle_threshold", settle_threshold, "positive");
    require(check_time > 0.0, "check_time", check_time, "positive");
    require(max_time > check_time, "max_time", max_time,
            "longer than --check-time " + format_number(check_time));
    require(max_time / check_time <= 1e6, "max_time", max_time,
            "at most 10^6 settling checks (--max-time / --check-time " + format_number(check_time) +
                ")");
    require(cloud_fraction > 0.0 && cloud_fraction <= 0.35, "cloud_fraction", cloud_fraction,
            "in (0, 0.35] (random insertion jams above)");
    require(start_jitter >= 0.0 && start_jitter <= 0.5, "start_jitter", start_jitter,
            "in [0, 0.5]");
    require(ranks >= 1 && ranks <= 64, "ranks", ranks, "between 1 and 64");
    if (!processors.empty()) {
        const auto grid = parse_processor_grid(processors);
        if (!grid || (*grid)[0] * (*grid)[1] * (*grid)[2] != ranks) {
            throw ParameterError("processors", processors,
                                 "must be PX,PY,PZ, whole numbers >= 1 with PX*PY*PZ = ranks " +
                                     std::to_string(ranks));
        }
    }
}

double PourParams::diameter() const {
    return diameter_for_count(count, phi_target);
}

double PourParams::cloud_top() const {
    // Centres of spheres wholly inside the cloud lie in a box narrower by d on every side,
    // so the cloud's solid fraction is counted over that box: N v = f (L - d)² (h - d).
    const double d = diameter();
    const double solid = static_cast<double>(count) * std::numbers::pi / 6.0 * d * d * d;
    const Container container;
    const double width = container.x_max - container.x_min - d;
    const double depth = container.z_max - container.z_min - d;
    return container.floor + d + solid / (cloud_fraction * width * depth);
}

std::uint64_t next_prime(std::uint64_t n) {
    const auto is_prime = [](std::uint64_t k) {
        if (k < 2) {
            return false;
        }
        for (std::uint64_t f = 2; f * f <= k; ++f) {
            if (k % f == 0) {
                return false;
            }
        }
        return true;
    };
    while (!is_prime(n)) {
        ++n;
    }
    return n;
}

LiggghtsSeeds liggghts_seeds(std::uint64_t seed) {
    Random random(seed);
    const auto draw = [&random] { return next_prime(10'007 + random.below(100'000'000)); };
    LiggghtsSeeds seeds;
    seeds.particle_template = draw();
    seeds.distribution = draw();
    seeds.insertion = draw();
    return seeds;
}

}  // namespace sgmp::reference
