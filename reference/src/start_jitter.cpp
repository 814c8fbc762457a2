#include "sgmp/reference/start_jitter.hpp"

namespace sgmp::reference {
namespace {

bool fits(const std::vector<Vec3>& centers, std::size_t moving, const Vec3& candidate,
          double radius, const Container& container) {
    if (container.penetration(candidate, radius) > 0.0) {
        return false;
    }
    const double contact_squared = 4.0 * radius * radius;
    for (std::size_t j = 0; j < centers.size(); ++j) {
        if (j != moving && (centers[j] - candidate).squaredNorm() < contact_squared) {
            return false;
        }
    }
    return true;
}

}  // namespace

std::size_t jitter_horizontally(std::vector<Vec3>& centers, double radius, double amplitude,
                                const Container& container, Random& random) {
    std::size_t moved = 0;
    if (amplitude <= 0.0) {
        return moved;
    }
    for (std::size_t i = 0; i < centers.size(); ++i) {
        for (int attempt = 0; attempt < 10; ++attempt) {
            double dx = 0.0;
            double dz = 0.0;
            do {  // uniform in the disk, by rejection from its square
                dx = random.uniform(-1.0, 1.0);
                dz = random.uniform(-1.0, 1.0);
            } while (dx * dx + dz * dz > 1.0);
            const Vec3 candidate = centers[i] + amplitude * Vec3(dx, 0.0, dz);
            if (fits(centers, i, candidate, radius, container)) {
                centers[i] = candidate;
                ++moved;
                break;
            }
        }
    }
    return moved;
}

}  // namespace sgmp::reference
