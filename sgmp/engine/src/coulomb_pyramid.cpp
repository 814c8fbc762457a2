#include "sgmp/engine/coulomb_pyramid.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace sgmp::engine {

std::array<Vec3, kPyramidEdges> coulomb_pyramid(const Vec3& normal, double friction) {
    const Vec3 helper = std::abs(normal.x()) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
    const Vec3 t1 = normal.cross(helper).normalized();
    const Vec3 t2 = normal.cross(t1);
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

}  // namespace sgmp::engine
