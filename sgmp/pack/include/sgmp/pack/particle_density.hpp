#pragma once
/// @file particle_density.hpp
/// The density of each sphere, where the pack states one: `particle_density` (one density
/// for every sphere, `sgmp convert --density`), else the blend's per-species densities
/// (`size_modes` items diameter:fraction:density, species i the i-th item), in the unit the
/// user gave them (kg/m³ with metres is LAMMPS' `units si`). A sphere's mass is
/// m = ρ·(π/6)·D³, D its diameter in the file's length unit.
#include <optional>
#include <vector>

#include "sgmp/pack/pack.hpp"

namespace sgmp {

/// One density per particle, in pack order; nullopt when the pack states none (or its
/// size_modes lack a density for some species a particle belongs to).
std::optional<std::vector<double>> particle_densities(const Pack& pack);

/// Whether densities vary between species (a mass column says more than a density key).
bool densities_vary(const std::vector<double>& densities);

/// m = ρ·(π/6)·(2r)³.
double sphere_mass(double density, double radius);

}  // namespace sgmp
