#include "sgmp/pack/periodic_images.hpp"

namespace sgmp {

std::vector<Vec3> periodic_image_centers(const Vec3& c, const Container& container, double margin) {
    std::vector<Vec3> images;
    if (!container.periodic) {
        return images;
    }
    // k periods away (k ≥ 1) while the image lies within `margin` of the cell: one period
    // for any margin up to the period, more for a wider one.
    const auto shifts = [&](double v, double lo, double hi) {
        const double period = hi - lo;
        std::vector<double> s{0.0};
        for (int k = 1; v - lo < margin - (k - 1) * period; ++k) {
            s.push_back(k * period);
        }
        for (int k = 1; hi - v < margin - (k - 1) * period; ++k) {
            s.push_back(-k * period);
        }
        return s;
    };
    for (const double sx : shifts(c.x(), container.x_min, container.x_max)) {
        for (const double sz : shifts(c.z(), container.z_min, container.z_max)) {
            if (sx != 0.0 || sz != 0.0) {
                images.push_back(c + Vec3(sx, 0.0, sz));
            }
        }
    }
    return images;
}

ImagedParticles with_periodic_images(const std::vector<Particle>& particles,
                                     const Container& container, double margin) {
    ImagedParticles out;
    out.particles = particles;
    out.originals = particles.size();
    out.source.resize(particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i) {
        out.source[i] = i;
    }
    for (std::size_t i = 0; i < particles.size(); ++i) {
        for (const Vec3& at : periodic_image_centers(particles[i].center, container, margin)) {
            Particle image = particles[i];
            image.center = at;
            out.particles.push_back(image);
            out.source.push_back(i);
        }
    }
    return out;
}

}  // namespace sgmp
