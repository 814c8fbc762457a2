#include "sgmp/pack/sphere_box_volume.hpp"

#include "sgmp/pack/ball_cut.hpp"

#include <algorithm>
#include <array>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "sgmp/pack/metadata.hpp"

namespace sgmp {
namespace {

constexpr double kPi = std::numbers::pi;

/// Area of the disk of radius rho with z >= b (a circular segment; b may have any sign).
double half_plane_area(double rho, double b) {
    if (b >= rho) {
        return 0.0;
    }
    if (b <= -rho) {
        return kPi * rho * rho;
    }
    return rho * rho * std::acos(b / rho) - b * std::sqrt(rho * rho - b * b);
}

/// ∫ √(ρ² − y²) dy.
double segment_primitive(double rho, double y) {
    const double s = std::clamp(y / rho, -1.0, 1.0);
    return 0.5 * (y * std::sqrt(std::max(0.0, rho * rho - y * y)) + rho * rho * std::asin(s));
}

/// Area of the disk with y >= a and z >= b, for a, b >= 0.
double quadrant_area_nonnegative(double rho, double a, double b) {
    if (a * a + b * b >= rho * rho) {
        return 0.0;
    }
    const double y_end = std::sqrt(rho * rho - b * b);
    return segment_primitive(rho, y_end) - segment_primitive(rho, a) - b * (y_end - a);
}

/// Area of the disk with y >= a and z >= b, any signs (reflections reduce to a, b >= 0).
double quadrant_area(double rho, double a, double b) {
    if (a < 0.0) {
        return half_plane_area(rho, b) - quadrant_area(rho, -a, b);
    }
    if (b < 0.0) {
        return half_plane_area(rho, a) - quadrant_area(rho, a, -b);
    }
    return quadrant_area_nonnegative(rho, a, b);
}

/// Position where the box clips the sphere along one axis, relative to the centre.
struct AxisCut {
    double lo;   // lower bound relative to the centre, clamped to [-r, r]
    double hi;   // upper bound relative to the centre, clamped to [-r, r]
    bool clips;  // true when a bound lies strictly inside (-r, r)
};

AxisCut cut_axis(double center, double radius, double lo, double hi) {
    const double rel_lo = lo - center;
    const double rel_hi = hi - center;
    return AxisCut{std::clamp(rel_lo, -radius, radius), std::clamp(rel_hi, -radius, radius),
                   (rel_lo > -radius) || (rel_hi < radius)};
}

/// ∫ π(r² − u²) du over [u0, u1]: the sphere between two parallel planes.
double slab_volume(double radius, double u0, double u1) {
    const auto primitive = [radius](double u) {
        return kPi * (radius * radius * u - u * u * u / 3.0);
    };
    return primitive(u1) - primitive(u0);
}

boost::math::quadrature::tanh_sinh<double>& integrator() {
    static thread_local boost::math::quadrature::tanh_sinh<double> instance;
    return instance;
}

constexpr int kGaussNodes = 32;

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n, once).
struct GaussLegendre {
    std::array<double, kGaussNodes> x{};
    std::array<double, kGaussNodes> w{};
    GaussLegendre() {
        for (int i = 0; i < kGaussNodes; ++i) {
            double z = std::cos(kPi * (i + 0.75) / (kGaussNodes + 0.5));
            double derivative = 1.0;
            for (int iteration = 0; iteration < 100; ++iteration) {
                double p0 = 1.0;
                double p1 = z;
                for (int k = 2; k <= kGaussNodes; ++k) {
                    const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                derivative = kGaussNodes * (z * p1 - p0) / (z * z - 1.0);
                const double step = p1 / derivative;
                z -= step;
                if (std::abs(step) < 1e-16) {
                    break;
                }
            }
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * derivative * derivative);
        }
    }
};

/// ∫_a^b f(u) du by Gauss–Legendre in t with u = a + (b − a)(1 − cos t)/2, t ∈ [0, π].
template <class F>
double integrate_smoothed(F&& f, double a, double b) {
    static const GaussLegendre rule;
    const double half = 0.5 * kPi;
    double sum = 0.0;
    for (int i = 0; i < kGaussNodes; ++i) {
        const double t = half * (rule.x[i] + 1.0);
        const double u = a + (b - a) * 0.5 * (1.0 - std::cos(t));
        sum += rule.w[i] * f(u) * 0.5 * (b - a) * std::sin(t);
    }
    return sum * half;
}

/// ∫ A(u) du where A is the disk-rectangle area of slice u, split at the break points
/// where the slice's disk meets an edge line or corner of the rectangle.
double sliced_volume(double radius, const AxisCut& along, const AxisCut& first,
                     const AxisCut& second, SphereBoxQuadrature quadrature) {
    std::vector<double> breaks{along.lo, along.hi};
    const auto add_break = [&](double rho_squared) {
        const double u_squared = radius * radius - rho_squared;
        if (u_squared > 0.0) {
            const double u = std::sqrt(u_squared);
            for (const double candidate : {-u, u}) {
                if (candidate > along.lo && candidate < along.hi) {
                    breaks.push_back(candidate);
                }
            }
        }
    };
    const std::array<double, 2> first_edges{first.lo, first.hi};
    const std::array<double, 2> second_edges{second.lo, second.hi};
    for (const double e : first_edges) {
        add_break(e * e);
    }
    for (const double e : second_edges) {
        add_break(e * e);
    }
    for (const double e1 : first_edges) {
        for (const double e2 : second_edges) {
            add_break(e1 * e1 + e2 * e2);
        }
    }
    std::sort(breaks.begin(), breaks.end());

    const auto slice_area = [&](double u) {
        const double rho = std::sqrt(std::max(0.0, radius * radius - u * u));
        return disk_rectangle_area(rho, first.lo, first.hi, second.lo, second.hi);
    };
    constexpr double kTolerance = 1e-14;
    double volume = 0.0;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        if (breaks[i + 1] > breaks[i] && quadrature == SphereBoxQuadrature::GaussLegendre) {
            volume += integrate_smoothed(slice_area, breaks[i], breaks[i + 1]);
        } else if (breaks[i + 1] > breaks[i]) {
            try {
                volume += integrator().integrate(slice_area, breaks[i], breaks[i + 1], kTolerance);
            } catch (const std::exception&) {  // boost's text names its internals only
                throw std::invalid_argument("the volume of a sphere of radius " +
                                            format_number(radius) +
                                            " cut by the region cannot be integrated");
            }
        }
    }
    return std::clamp(volume, 0.0, 4.0 / 3.0 * kPi * radius * radius * radius);
}

}  // namespace

double disk_rectangle_area(double rho, double y0, double y1, double z0, double z1) {
    if (rho <= 0.0 || y1 <= y0 || z1 <= z0) {
        return 0.0;
    }
    // Bounds beyond the disk act like infinite ones; clamping keeps the arithmetic finite.
    const double limit = 2.0 * rho;
    y0 = std::clamp(y0, -limit, limit);
    y1 = std::clamp(y1, -limit, limit);
    z0 = std::clamp(z0, -limit, limit);
    z1 = std::clamp(z1, -limit, limit);
    const double area = quadrant_area(rho, y0, z0) - quadrant_area(rho, y1, z0) -
                        quadrant_area(rho, y0, z1) + quadrant_area(rho, y1, z1);
    return std::clamp(area, 0.0, kPi * rho * rho);
}

double packing_fraction(const std::vector<Particle>& particles, const Box& region) {
    const double volume = region.volume();
    if (!(volume > 0.0)) {
        throw std::invalid_argument("packing fraction of an empty region");
    }
    double solid = 0.0;
    for (const auto& p : particles) {
        solid += sphere_box_volume(p.center, p.radius, region);
    }
    return solid / volume;
}

double packing_fraction(const Pack& pack, const Box& region) {
    return packing_fraction(pack.particles, region);
}

double sphere_box_volume(const Vec3& center, double radius, const Box& box,
                         SphereBoxQuadrature quadrature) {
    if (radius <= 0.0) {
        return 0.0;
    }
    // Entirely outside: the nearest point of the box is farther than the radius.
    const Vec3 nearest = center.cwiseMax(box.lo).cwiseMin(box.hi);
    if ((nearest - center).squaredNorm() >= radius * radius) {
        return 0.0;
    }
    // Entirely inside: the farthest corner of the box is within the radius (distances over
    // the radius, so a radius beyond 10¹⁵⁴, whose square overflows, still decides).
    const Vec3 far = (center - box.lo).cwiseAbs().cwiseMax((center - box.hi).cwiseAbs()) / radius;
    if (far.squaredNorm() <= 1.0) {
        const Vec3 side = box.hi - box.lo;
        return side.x() * side.y() * side.z();
    }
    std::array<AxisCut, 3> cuts{};
    int clipped_axes = 0;
    for (int axis = 0; axis < 3; ++axis) {
        cuts[axis] = cut_axis(center[axis], radius, box.lo[axis], box.hi[axis]);
        clipped_axes += cuts[axis].clips ? 1 : 0;
    }
    if (clipped_axes == 0) {
        return 4.0 / 3.0 * kPi * radius * radius * radius;
    }
    if (clipped_axes == 1) {
        for (const auto& cut : cuts) {
            if (cut.clips) {
                return slab_volume(radius, cut.lo, cut.hi);
            }
        }
    }
    if (clipped_axes == 2) {
        // Closed form (ball_cut.hpp): the two clipped axes bound the ball, the third does not.
        const AxisCut* first = nullptr;
        const AxisCut* second = nullptr;
        for (const auto& cut : cuts) {
            if (cut.clips) {
                (first == nullptr ? first : second) = &cut;
            }
        }
        return ball_cut_volume(radius, first->lo, first->hi, second->lo, second->hi);
    }
    // All three axes clip: integrate the slices along one of them.
    int along = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (!cuts[axis].clips) {
            along = axis;
        }
    }
    const int first = (along + 1) % 3;
    const int second = (along + 2) % 3;
    return sliced_volume(radius, cuts[along], cuts[first], cuts[second], quadrature);
}

}  // namespace sgmp
