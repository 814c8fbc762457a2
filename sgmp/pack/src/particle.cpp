#include "sgmp/pack/particle.hpp"

namespace sgmp {

double surface_gap(const Particle& a, const Particle& b) {
    return (a.center - b.center).norm() - a.radius - b.radius;
}

bool overlaps(const Particle& a, const Particle& b) {
    const double reach = a.radius + b.radius;
    return (a.center - b.center).squaredNorm() < reach * reach;
}

}  // namespace sgmp
