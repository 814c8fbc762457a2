#include "sgmp/metrics/sphere_values.hpp"

#include <algorithm>

#include "sgmp/metrics/neighbour_index.hpp"
#include "sgmp/metrics/voronoi.hpp"
#include "sgmp/pack/periodic_images.hpp"

namespace sgmp::metrics {

std::vector<double> sphere_contact_numbers(const std::vector<Particle>& input,
                                           const Container& container, double gap_over_d) {
    std::vector<double> z(input.size(), 0.0);
    if (input.empty()) {
        return z;
    }
    double r_max = 0.0;
    double radius_sum = 0.0;
    for (const Particle& p : input) {
        r_max = std::max(r_max, p.radius);
        radius_sum += p.radius;
    }
    const double d = 2.0 * radius_sum / static_cast<double>(input.size());
    const double gap = gap_over_d * d;
    // Images across periodic faces are neighbours, never spheres of their own (a file's
    // centres may lie a period out: wrapped first).
    std::vector<Particle> wrapped = input;
    for (Particle& p : wrapped) {
        p.center = container.wrapped(p.center);
    }
    const std::vector<Particle> particles =
        with_periodic_images(wrapped, container, 2.0 * r_max + gap).particles;
    const NeighbourIndex index(particles);
    std::vector<Index> found;
    for (std::size_t i = 0; i < input.size(); ++i) {
        const Particle& a = particles[i];
        index.within(a.center, a.radius + r_max + gap, found);
        for (const Index j : found) {
            const Particle& b = particles[j];
            if (j != i && (a.center - b.center).norm() - a.radius - b.radius <= gap) {
                z[i] += 1.0;
            }
        }
    }
    return z;
}

std::vector<double> sphere_local_phi(const std::vector<Particle>& particles,
                                     const Container& container) {
    double top = container.floor;
    for (const Particle& p : particles) {
        top = std::max(top, p.center.y() + p.radius);
    }
    VoronoiOptions options;
    options.keep_local = true;
    const Box everything = container.box_up_to(top + 1.0);
    std::vector<Particle> wrapped = particles;  // a period out: back into the cell
    for (Particle& p : wrapped) {
        p.center = container.wrapped(p.center);
    }
    return voronoi_local_phi(wrapped, container, everything, options).local;
}

}  // namespace sgmp::metrics
