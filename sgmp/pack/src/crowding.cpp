#include "sgmp/pack/crowding.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace sgmp {
namespace {

struct Keyed {
    std::array<std::int64_t, 3> cube{};
    std::size_t index = 0;
};

/// The cube index along one axis, clamped far beyond any real pack (±2^62) so that the
/// conversion is defined for any finite coordinate; a clamp only merges cubes, so it can
/// only add to a count.
std::int64_t cube_of(double x, double side) {
    constexpr double kLimit = 4.0e18;
    return static_cast<std::int64_t>(std::clamp(std::floor(x / side), -kLimit, kLimit));
}

}  // namespace

std::optional<Crowding> overcrowded_cube(const std::vector<Particle>& particles) {
    if (particles.size() <= kMaxCentresPerCube) {
        return std::nullopt;
    }
    double r_min = particles.front().radius;
    for (const Particle& p : particles) {
        if (!(p.radius > 0.0) || !std::isfinite(p.radius) || !p.center.allFinite()) {
            return std::nullopt;
        }
        r_min = std::min(r_min, p.radius);
    }
    const double side = 2.0 * r_min;
    std::vector<Keyed> keyed(particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Vec3& c = particles[i].center;
        keyed[i] = {{cube_of(c.x(), side), cube_of(c.y(), side), cube_of(c.z(), side)}, i};
    }
    std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
        return a.cube != b.cube ? a.cube < b.cube : a.index < b.index;
    });
    std::optional<Crowding> first;
    for (std::size_t begin = 0; begin < keyed.size();) {
        std::size_t end = begin + 1;
        while (end < keyed.size() && keyed[end].cube == keyed[begin].cube) {
            ++end;
        }
        const std::size_t centres = end - begin;
        if (centres > kMaxCentresPerCube && (!first || keyed[begin].index < first->index)) {
            first = Crowding{keyed[begin].index, centres, side};
        }
        begin = end;
    }
    return first;
}

}  // namespace sgmp
