#include "sgmp/metrics/rdf.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "sgmp/metrics/pack_content_error.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"

namespace sgmp::metrics {

Box center_space(const std::vector<Particle>& particles, const Container& container,
                 double mean_radius) {
    double top = -std::numeric_limits<double>::infinity();
    for (const Particle& p : particles) {
        top = std::max(top, p.center.y());
    }
    const Box space{Vec3(container.x_min + mean_radius, container.floor + mean_radius,
                         container.z_min + mean_radius),
                    Vec3(container.x_max - mean_radius, top, container.z_max - mean_radius)};
    if (!((space.hi - space.lo).array() > 0.0).all()) {
        throw PackContentError(  // the pack's radii and container: bad input, not usage
            "g(r): the space of particle centres (container shrunk by the mean radius, up to the "
            "highest centre) is empty");
    }
    return space;
}

Box container_space(const std::vector<Particle>& particles, const Container& container) {
    double top = -std::numeric_limits<double>::infinity();
    for (const Particle& p : particles) {
        top = std::max(top, p.center.y() + p.radius);
    }
    const Box space = container.box_up_to(top);
    if (!((space.hi - space.lo).array() > 0.0).all()) {
        throw PackContentError("g(r): the pack's top lies below the container floor");
    }
    return space;
}

bool shells_inside(const Vec3& center, double outer, const Box& space) {
    return ((center - space.lo).array() >= outer).all() &&
           ((space.hi - center).array() >= outer).all();
}

void add_shell_volumes(const Vec3& center, double width, std::size_t bins, const Box& space,
                       std::vector<double>& out) {
    double inner = 0.0;
    for (std::size_t k = 0; k < bins; ++k) {
        const double outer = sphere_box_volume(center, bin_outer(k, width), space,
                                               SphereBoxQuadrature::GaussLegendre);
        out[k] += outer - inner;
        inner = outer;
    }
}

void normalise(Rdf& rdf) {
    const std::size_t bins = rdf.pairs.size();
    if (rdf.density_rule == RdfDensity::Space) {
        rdf.density = rdf.space_density;
    } else {
        double pairs = 0.0;
        double volume = 0.0;
        for (std::size_t k = 0; k < bins; ++k) {
            pairs += static_cast<double>(rdf.pairs[k]);
            volume += rdf.shell_volume[k];
        }
        rdf.density = volume > 0.0 && pairs > 0.0 ? pairs / volume : rdf.space_density;
    }
    rdf.r_over_d.resize(bins);
    rdf.g.resize(bins);
    for (std::size_t k = 0; k < bins; ++k) {
        rdf.r_over_d[k] = static_cast<double>(k) * rdf.bin_width_over_d;
        const double expected = rdf.density * rdf.shell_volume[k];
        rdf.g[k] = expected > 0.0 ? static_cast<double>(rdf.pairs[k]) / expected : 0.0;
    }
    const auto window_g = [&](int w) {
        const double expected = rdf.density * rdf.split_volume[w];
        return expected > 0.0 ? static_cast<double>(rdf.split_pairs[w]) / expected : 0.0;
    };
    const double high = window_g(1);
    rdf.split_ratio = high > 0.0 ? window_g(0) / high : 0.0;
}

ThesisRdf thesis_rdf(const std::vector<Particle>& particles, const Box& region, double phi,
                     double width, std::size_t bins) {
    ThesisRdf result;
    result.phi = phi;
    result.g.assign(bins, 0.0);
    const Vec3 middle = 0.5 * (region.lo + region.hi);
    std::size_t origin = particles.size();
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < particles.size(); ++i) {
        if (!region.contains(particles[i].center)) {
            continue;
        }
        ++result.region_count;
        const double distance = (particles[i].center - middle).squaredNorm();
        if (distance < best) {
            best = distance;
            origin = i;
        }
    }
    if (origin == particles.size()) {
        return result;
    }
    result.origin_id = particles[origin].id;
    std::vector<std::int64_t> counts(bins, 0);
    for (std::size_t j = 0; j < particles.size(); ++j) {
        if (j == origin || !region.contains(particles[j].center)) {
            continue;
        }
        const double r = (particles[j].center - particles[origin].center).norm();
        const auto k = bin_of(r, 1.0 / width);
        if (k < bins) {
            ++counts[k];
        }
    }
    const auto n = static_cast<double>(result.region_count);
    for (std::size_t k = 0; k < bins; ++k) {
        const double r = static_cast<double>(k) * width;
        const double shell =
            4.0 * std::numbers::pi / 3.0 *
            (std::pow(r + 0.5 * width, 3) - std::pow(std::max(0.0, r - 0.5 * width), 3));
        result.g[k] = static_cast<double>(counts[k]) / n / (phi * shell);
    }
    return result;
}

}  // namespace sgmp::metrics
