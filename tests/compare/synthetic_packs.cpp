#include "synthetic_packs.hpp"

#include <cmath>
#include <vector>

#include "sgmp/pack/random.hpp"

namespace sgmp::testing {
namespace {

std::vector<Vec3> basis(Lattice lattice) {
    switch (lattice) {
        case Lattice::simple_cubic:
            return {Vec3(0, 0, 0)};
        case Lattice::bcc:
            return {Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5)};
        case Lattice::fcc:
            return {Vec3(0, 0, 0), Vec3(0.5, 0.5, 0), Vec3(0.5, 0, 0.5), Vec3(0, 0.5, 0.5)};
    }
    return {};
}

/// Cube side of the conventional cell when nearest neighbours are d apart.
double cell_side(Lattice lattice, double d) {
    switch (lattice) {
        case Lattice::simple_cubic:
            return d;
        case Lattice::bcc:
            return 2.0 * d / std::sqrt(3.0);
        case Lattice::fcc:
            return std::sqrt(2.0) * d;
    }
    return d;
}

void add_metadata(Pack& pack, const std::string& generator, double d, const Container& c) {
    pack.metadata.set("generator", generator);
    pack.metadata.set_integer("count", static_cast<long long>(pack.particles.size()));
    pack.metadata.set_number("diameter", d);
    pack.metadata.set("container", c.to_string());
}

}  // namespace

Pack lattice_pack(Lattice lattice, double d, const Box& box, const Vec3& offset) {
    Pack pack;
    const double a = cell_side(lattice, d);
    const Vec3 origin = box.lo + offset;
    const Eigen::Vector3i cells = ((box.hi - origin) / a).array().floor().cast<int>() + 1;
    std::int64_t id = 0;
    for (int i = -1; i <= cells.x(); ++i) {
        for (int j = -1; j <= cells.y(); ++j) {
            for (int k = -1; k <= cells.z(); ++k) {
                for (const Vec3& b : basis(lattice)) {
                    const Vec3 c = origin + a * (Vec3(i, j, k) + b);
                    if (box.contains(c)) {
                        pack.particles.push_back(Particle{++id, c, 0.5 * d, 0});
                    }
                }
            }
        }
    }
    Container container;
    container.x_min = box.lo.x() - d;
    container.x_max = box.hi.x() + d;
    container.z_min = box.lo.z() - d;
    container.z_max = box.hi.z() + d;
    container.floor = box.lo.y() - d;
    add_metadata(pack, "lattice", d, container);
    return pack;
}

Pack jittered_fcc_pack(std::size_t count, double spacing, double jitter, std::uint64_t seed) {
    const Container container;
    const double d = diameter_for_count(count);
    const double r = 0.5 * d;
    const double a = std::sqrt(2.0) * spacing * d;
    const double lo = container.x_min + r + jitter * d;
    const double hi = container.x_max - r - jitter * d;
    const int cells = static_cast<int>(std::floor((hi - lo) / a));
    Random random(seed);
    Pack pack;
    pack.particles.reserve(count);
    // Half-cell layers in y: layer 2k holds basis points with y-offset 0, layer 2k+1 the rest.
    for (int layer = 0; pack.particles.size() < count; ++layer) {
        const double y = container.floor + r + jitter * d + 0.5 * a * layer;
        const int parity = layer % 2;
        for (int i = 0; i <= 2 * cells && pack.particles.size() < count; ++i) {
            for (int k = 0; k <= 2 * cells && pack.particles.size() < count; ++k) {
                if ((i + k + parity) % 2 != 0) {
                    continue;
                }
                Vec3 c(lo + 0.5 * a * i, y, lo + 0.5 * a * k);
                for (int axis = 0; axis < 3; ++axis) {
                    c[axis] += random.uniform(-jitter, jitter) * d;
                }
                pack.particles.push_back(
                    Particle{static_cast<std::int64_t>(pack.particles.size() + 1), c, r,
                             static_cast<int>(random.below(10))});
            }
        }
    }
    add_metadata(pack, "jittered-fcc", d, container);
    pack.metadata.set_number("spacing", spacing);
    pack.metadata.set_number("jitter", jitter);
    pack.metadata.set_integer("seed", static_cast<long long>(seed));
    return pack;
}

Pack uniform_pack(std::size_t count, double d, const Box& box, std::uint64_t seed) {
    Random random(seed);
    Pack pack;
    for (std::size_t i = 0; i < count; ++i) {
        Vec3 c;
        for (int axis = 0; axis < 3; ++axis) {
            c[axis] = random.uniform(box.lo[axis], box.hi[axis]);
        }
        pack.particles.push_back(Particle{static_cast<std::int64_t>(i + 1), c, 0.5 * d, 0});
    }
    Container container;
    container.x_min = box.lo.x() - 0.5 * d;
    container.x_max = box.hi.x() + 0.5 * d;
    container.z_min = box.lo.z() - 0.5 * d;
    container.z_max = box.hi.z() + 0.5 * d;
    container.floor = box.lo.y() - 0.5 * d;
    add_metadata(pack, "uniform", d, container);
    pack.metadata.set_integer("seed", static_cast<long long>(seed));
    return pack;
}

}  // namespace sgmp::testing
