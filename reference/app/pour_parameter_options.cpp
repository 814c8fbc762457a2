#include "physics_options.hpp"

namespace sgmp::reference {

void add_physics_options(CLI::App& command, PourParams& p) {
    command.add_option("--restitution", p.restitution, "Normal coefficient of restitution e")
        ->capture_default_str();
    command
        .add_option("--rolling-friction", p.rolling_friction,
                    "Rolling friction coefficient (constant directional torque)")
        ->capture_default_str();
    command
        .add_option("--youngs-modulus", p.youngs_modulus,
                    "Young's modulus E in Pa (must exceed 5e6)")
        ->capture_default_str();
    command.add_option("--poisson-ratio", p.poisson_ratio, "Poisson's ratio nu")
        ->capture_default_str();
    command.add_option("--density", p.density, "Particle density in kg/m^3")->capture_default_str();
    command.add_option("--gravity", p.gravity, "Gravitational acceleration in m/s^2 (along -Y)")
        ->capture_default_str();
    command
        .add_option("--timestep-fraction", p.timestep_fraction,
                    "Time step as a fraction of the Rayleigh time")
        ->capture_default_str();
    command
        .add_option("--settle-threshold", p.settle_threshold,
                    "Settled when the translational kinetic energy per particle stays "
                    "below this times m g d at two consecutive checks")
        ->capture_default_str();
    command.add_option("--check-time", p.check_time, "Simulated seconds between settling checks")
        ->capture_default_str();
}

}  // namespace sgmp::reference
