#pragma once
/// @file periodic_images.hpp
/// A pack with periodic sides (Container::periodic) as plain spheres: the particles, then
/// the images, one period away in x, in z or in both, of every particle within `margin` of
/// a lateral face. Any pair search over the list then finds the pairs across the faces: the
/// pair (i, image of j) stands for the minimum-image pair (i, j), met once more as
/// (j, image of i), so a search counts it only when i < j.
#include <cstddef>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp {

struct ImagedParticles {
    std::vector<Particle> particles;  ///< the originals (first `originals`), then images
    std::vector<std::size_t> source;  ///< the original of each entry (itself for originals)
    std::size_t originals = 0;
};

/// The images of one centre c, in the order (x shift, then z shift) each of 0, +period
/// (c within `margin` of the low face), −period (within `margin` of the high face), leaving
/// out c itself; none without periodic sides. A margin wider than a period adds the images
/// k periods away while they lie within it (+2·period, … after +period; likewise below).
std::vector<Vec3> periodic_image_centers(const Vec3& c, const Container& container, double margin);

/// The list above; without periodic sides, the particles alone.
ImagedParticles with_periodic_images(const std::vector<Particle>& particles,
                                     const Container& container, double margin);

}  // namespace sgmp
