#pragma once
// The invariants every SGMP pack keeps, asserted by brute force (brute_force.hpp) and by the
// engine's own check: no pair overlaps by more than 1e-9·d, no sphere crosses a wall or the
// floor by more than that.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "brute_force.hpp"
#include "sgmp/engine/pack_checks.hpp"

namespace sgmp::engine::testing {

/// Asserts the overlap and containment invariants of a pack of spheres of mean diameter d.
inline void check_no_overlap_and_inside(const std::vector<Particle>& particles, double d) {
    // 1e-9·d: the invariant of every SGMP pack (the hard-sphere finish leaves 1e-10·d).
    const double tolerance = 1e-9 * d;
    BOOST_TEST(worst_pair_gap(particles) >= -tolerance);
    BOOST_TEST(worst_penetration(particles, Container{}) <= tolerance);
    const PackCheck check = check_pack(particles, Container{}, tolerance, INFINITY);
    BOOST_TEST(check.overlaps == 0u);
    BOOST_TEST(check.outside == 0u);
}

}  // namespace sgmp::engine::testing
