#include "sgmp/metrics/packing_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sgmp/metrics/parallel.hpp"
#include "sgmp/pack/ball_cut.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"

namespace sgmp::metrics {
namespace {

constexpr std::size_t kChunk = 8192;

/// Volume of the ball of radius r between the planes u0 ≤ u ≤ u1 (relative to its
/// centre, clamped to [−r, r]): ∫ π(r² − u²) du.
double ball_slab(double r, double u0, double u1) {
    u0 = std::clamp(u0, -r, r);
    u1 = std::clamp(u1, -r, r);
    const auto primitive = [r](double u) {
        return std::numbers::pi * (r * r * u - u * u * u / 3.0);
    };
    return primitive(u1) - primitive(u0);
}

/// True when the ball lies within the box's bounds along `axis`.
bool inside_along(const Particle& p, const Box& box, int axis) {
    return p.center[axis] - p.radius >= box.lo[axis] && p.center[axis] + p.radius <= box.hi[axis];
}

bool misses(const Particle& p, const Box& box) {
    const Vec3 nearest = p.center.cwiseMax(box.lo).cwiseMin(box.hi);
    return (nearest - p.center).squaredNorm() >= p.radius * p.radius;
}

}  // namespace

PhiProfile packing_fraction_profile(const std::vector<Particle>& particles,
                                    const Box& cross_section, double y0, double y1,
                                    double thickness, unsigned threads) {
    if (!(thickness > 0.0) || !(y1 > y0)) {
        throw std::invalid_argument("phi profile needs a positive slab thickness and y1 > y0");
    }
    PhiProfile profile;
    profile.y0 = y0;
    profile.thickness = thickness;
    // At least one slab: a slab thicker than the column is the column (the rounding guard
    // must not round a tiny quotient down to none).
    const auto slabs =
        static_cast<std::size_t>(std::max(1.0, std::ceil((y1 - y0) / thickness - 1e-12)));
    for (std::size_t k = 0; k < slabs; ++k) {
        profile.y_lo.push_back(y0 + static_cast<double>(k) * thickness);
        profile.y_hi.push_back(std::min(y1, y0 + static_cast<double>(k + 1) * thickness));
    }
    const double area = (cross_section.hi.x() - cross_section.lo.x()) *
                        (cross_section.hi.z() - cross_section.lo.z());
    const Box column{Vec3(cross_section.lo.x(), y0, cross_section.lo.z()),
                     Vec3(cross_section.hi.x(), y1, cross_section.hi.z())};
    using Volumes = std::vector<double>;
    const Volumes volumes = chunked_reduce(
        threads, particles.size(), kChunk, Volumes(slabs, 0.0),
        [&](Volumes& sums, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const Particle& p = particles[i];
                if (misses(p, column)) {
                    continue;
                }
                const double y = p.center.y();
                const double r = p.radius;
                const auto first =
                    static_cast<std::size_t>(std::max(0.0, std::floor((y - r - y0) / thickness)));
                const auto last = std::min(
                    slabs - 1,
                    static_cast<std::size_t>(std::max(0.0, std::floor((y + r - y0) / thickness))));
                const bool in_x = inside_along(p, cross_section, 0);
                const bool in_z = inside_along(p, cross_section, 2);
                // Cut along y only: closed form; by one vertical face too: ball_cut_volume;
                // by both (near the column's vertical edges): sphere_box_volume, Gauss–Legendre
                // (~1e-11).
                const int cut_axis = in_x ? 2 : 0;
                const double u0 = cross_section.lo[cut_axis] - p.center[cut_axis];
                const double u1 = cross_section.hi[cut_axis] - p.center[cut_axis];
                for (std::size_t k = first; k <= last; ++k) {
                    const double lo = profile.y_lo[k];
                    const double hi = profile.y_hi[k];
                    if (in_x && in_z) {
                        sums[k] += ball_slab(r, lo - y, hi - y);
                    } else if (in_x || in_z) {
                        sums[k] += ball_cut_volume(r, u0, u1, lo - y, hi - y);
                    } else {
                        const Box slab{Vec3(column.lo.x(), lo, column.lo.z()),
                                       Vec3(column.hi.x(), hi, column.hi.z())};
                        sums[k] += sphere_box_volume(p.center, r, slab,
                                                     SphereBoxQuadrature::GaussLegendre);
                    }
                }
            }
        },
        [](Volumes& total, const Volumes& partial) {
            for (std::size_t k = 0; k < total.size(); ++k) {
                total[k] += partial[k];
            }
        });
    profile.phi.resize(slabs);
    for (std::size_t k = 0; k < slabs; ++k) {
        profile.phi[k] = volumes[k] / (area * (profile.y_hi[k] - profile.y_lo[k]));
    }
    return profile;
}

}  // namespace sgmp::metrics
