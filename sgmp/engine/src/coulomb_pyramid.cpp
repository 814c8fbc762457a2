#include "sgmp/engine/coulomb_pyramid.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace sgmp::engine {
namespace {

/// The pyramid's tangent basis t₁, t₂ around `normal`.
std::pair<Vec3, Vec3> tangent_basis(const Vec3& normal) {
    const Vec3 helper = std::abs(normal.x()) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
    const Vec3 t1 = normal.cross(helper).normalized();
    return {t1, normal.cross(t1)};
}

}  // namespace

std::array<Vec3, kPyramidEdges> coulomb_pyramid(const Vec3& normal, double friction) {
    const auto [t1, t2] = tangent_basis(normal);
    const double mu = friction * std::cos(std::numbers::pi / kPyramidEdges);
    std::array<Vec3, kPyramidEdges> edges;
    for (int k = 0; k < kPyramidEdges; ++k) {
        const double theta = 2.0 * std::numbers::pi * k / kPyramidEdges;
        edges[static_cast<std::size_t>(k)] =
            normal + mu * (std::cos(theta) * t1 + std::sin(theta) * t2);
    }
    return edges;
}

double pyramid_inscribed_friction(double friction) {
    const double c = std::cos(std::numbers::pi / kPyramidEdges);
    return friction * c * c;
}

std::array<double, kPyramidEdges> pyramid_edge_forces(const Vec3& normal, double friction,
                                                      double normal_force, const Vec3& tangential) {
    std::array<double, kPyramidEdges> beta{};
    if (!(normal_force > 0.0)) {
        return beta;
    }
    const double mu = friction * std::cos(std::numbers::pi / kPyramidEdges);
    const auto [t1, t2] = tangent_basis(normal);
    const double x = mu > 0.0 ? tangential.dot(t1) / mu : 0.0;
    const double y = mu > 0.0 ? tangential.dot(t2) / mu : 0.0;
    // The sector [θₖ, θₖ₊₁] holding the direction of (x, y), and (x, y) = a·uₖ + b·uₖ₊₁.
    const double sector = 2.0 * std::numbers::pi / kPyramidEdges;
    double angle = std::atan2(y, x);
    if (angle < 0.0) {
        angle += 2.0 * std::numbers::pi;
    }
    const int k = std::min(static_cast<int>(angle / sector), kPyramidEdges - 1);
    const int j = (k + 1) % kPyramidEdges;
    const double tk = sector * k;
    const double tj = sector * (k + 1);
    const double det = std::sin(sector);  // sin(θⱼ − θₖ)
    double a = std::max(0.0, (x * std::sin(tj) - y * std::cos(tj)) / det);
    double b = std::max(0.0, (y * std::cos(tk) - x * std::sin(tk)) / det);
    if (a + b > normal_force) {
        const double scale = normal_force / (a + b);
        a *= scale;
        b *= scale;
    }
    const double rest = (normal_force - a - b) / kPyramidEdges;
    beta.fill(rest);
    beta[static_cast<std::size_t>(k)] += a;
    beta[static_cast<std::size_t>(j)] += b;
    return beta;
}

}  // namespace sgmp::engine
