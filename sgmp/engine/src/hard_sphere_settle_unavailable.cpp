// The settling of a build without COIN-OR CLP (SGMP_WITH_CLP=OFF): none.
#include <stdexcept>

#include "sgmp/engine/hard_sphere_settle.hpp"

namespace sgmp::engine {

bool lp_solver_available() {
    return false;
}

SettleStats settle_hard_spheres(std::vector<Particle>&, const Container&, double,
                                const SettleOptions&) {
    throw std::runtime_error(
        "the hard-sphere settling needs COIN-OR CLP; this build has none (SGMP_WITH_CLP=OFF)");
}

}  // namespace sgmp::engine
