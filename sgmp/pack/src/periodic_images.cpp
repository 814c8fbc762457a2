#include "sgmp/pack/periodic_images.hpp"

namespace sgmp {

ImagedParticles with_periodic_images(const std::vector<Particle>& particles,
                                     const Container& container, double margin) {
    ImagedParticles out;
    out.particles = particles;
    out.originals = particles.size();
    out.source.resize(particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i) {
        out.source[i] = i;
    }
    if (!container.periodic) {
        return out;
    }
    const double lx = container.x_max - container.x_min;
    const double lz = container.z_max - container.z_min;
    const auto shifts = [&](double v, double lo, double hi, double period, double(&s)[3]) {
        int n = 0;
        s[n++] = 0.0;
        if (v - lo < margin) {
            s[n++] = period;
        }
        if (hi - v < margin) {
            s[n++] = -period;
        }
        return n;
    };
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Particle& p = particles[i];
        double sx[3], sz[3];
        const int nx = shifts(p.center.x(), container.x_min, container.x_max, lx, sx);
        const int nz = shifts(p.center.z(), container.z_min, container.z_max, lz, sz);
        for (int a = 0; a < nx; ++a) {
            for (int b = 0; b < nz; ++b) {
                if (a == 0 && b == 0) {
                    continue;
                }
                Particle image = p;
                image.center += Vec3(sx[a], 0.0, sz[b]);
                out.particles.push_back(image);
                out.source.push_back(i);
            }
        }
    }
    return out;
}

}  // namespace sgmp
