#include "sgmp/reference/input_script.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/version.hpp"
#include "sgmp/reference/launcher.hpp"

namespace sgmp::reference {

std::string fill_template(const std::string& text,
                          const std::map<std::string, std::string>& values) {
    std::string out;
    out.reserve(text.size());
    std::size_t pos = 0;
    while (true) {
        const std::size_t open = text.find("{{", pos);
        if (open == std::string::npos) {
            out.append(text, pos, std::string::npos);
            return out;
        }
        const std::size_t close = text.find("}}", open + 2);
        if (close == std::string::npos) {
            throw std::invalid_argument("template: '{{' without '}}'");
        }
        std::string key = text.substr(open + 2, close - open - 2);
        std::size_t width = 0;  // "{{key:W}}" pads the value with spaces to W characters
        if (const auto colon = key.find(':'); colon != std::string::npos) {
            width = std::stoul(key.substr(colon + 1));
            key.resize(colon);
        }
        const auto value = values.find(key);
        if (value == values.end()) {
            throw std::invalid_argument("template: no value for placeholder '{{" + key + "}}'");
        }
        out.append(text, pos, open - pos).append(value->second);
        if (value->second.size() < width) {
            out.append(width - value->second.size(), ' ');
        }
        pos = close + 2;
    }
}

double domain_top(double start_top, double diameter, bool blend) {
    // Equal spheres thrown up in the first collisions rarely rise more than a few
    // diameters; a sphere leaving the box stops the run ("lost atoms"), never passes
    // silently.
    const double headroom = blend ? 1.0 : 0.25;
    return start_top + headroom * (start_top + 0.625) + 4.0 * diameter;
}

std::string processor_grid(const PourParams& p) {
    const Container c;
    const auto grid = p.processors.empty()
                          ? choose_processor_grid(p.ranks, c.x_max - c.x_min, c.z_max - c.z_min)
                          : parse_processor_grid(p.processors).value();
    return std::to_string(grid[0]) + " " + std::to_string(grid[1]) + " " + std::to_string(grid[2]);
}

namespace {

constexpr const char* kSideWalls =
    "fix wall_xl all wall/gran model hertz tangential history rolling_friction cdt primitive type "
    "1 xplane -0.625 tangential_damping ${tangential_damping}\n"
    "fix wall_xh all wall/gran model hertz tangential history rolling_friction cdt primitive type "
    "1 xplane 0.625 tangential_damping ${tangential_damping}\n"
    "fix wall_zl all wall/gran model hertz tangential history rolling_friction cdt primitive type "
    "1 zplane -0.625 tangential_damping ${tangential_damping}\n"
    "fix wall_zh all wall/gran model hertz tangential history rolling_friction cdt primitive type "
    "1 zplane 0.625 tangential_damping ${tangential_damping}";

/// The cloud's insertion: one template, distribution and insert/pack for equal spheres;
/// for a blend one template per species and one number-based distribution whose weights
/// are the species' counts over N, inserted by one insert/pack, which places exactly N·wᵢ
/// of each (separate insertions per species miss overlaps with the larger spheres already
/// placed: a trimodal cloud of 10⁴ had 346 overlapping pairs).
std::string insertion(const PourParams& p, const LiggghtsSeeds& seeds) {
    const std::string tail =
        " insert_every once overlapcheck yes all_in yes maxattempt 1000 particles_in_region "
        "${count} region cloud ntry_mc 10000";
    if (!p.is_blend()) {
        return "fix sphere_template all particletemplate/sphere " +
               std::to_string(seeds.particle_template) +
               " atom_type 1 density constant ${density} radius constant ${radius}\n"
               "fix sphere_sizes    all particledistribution/discrete " +
               std::to_string(seeds.distribution) +
               " 1 sphere_template 1.0\n"
               "fix insert_cloud    all insert/pack seed " +
               std::to_string(seeds.insertion) + " distributiontemplate sphere_sizes" + tail;
    }
    const std::vector<PourSpecies> species = p.species();
    const std::vector<LiggghtsSeeds> all = liggghts_species_seeds(p.seed, species.size());
    std::string text;
    std::string weights;
    std::size_t templates = 0;
    for (std::size_t i = 0; i < species.size(); ++i) {
        if (species[i].count == 0) {
            continue;
        }
        const std::string k = std::to_string(i + 1);
        text += "# species " + k + ": " + std::to_string(species[i].count) +
                " spheres of d = " + format_number(species[i].diameter) + " m\n";
        text += "fix template_" + k + " all particletemplate/sphere " +
                std::to_string(all[i].particle_template) + " atom_type 1 density constant " +
                format_number(species[i].density) + " radius constant " +
                format_number(species[i].diameter / 2.0) + "\n";
        weights +=
            " template_" + k + " " +
            format_number(static_cast<double>(species[i].count) / static_cast<double>(p.count));
        ++templates;
    }
    text += "fix sphere_sizes all particledistribution/discrete/numberbased " +
            std::to_string(seeds.distribution) + " " + std::to_string(templates) + weights + "\n";
    text += "fix insert_cloud all insert/pack seed " + std::to_string(seeds.insertion) +
            " distributiontemplate sphere_sizes" + tail;
    return text;
}

/// The radius the time step and the neighbour skin are set from: d/2 for equal spheres;
/// for a blend the smallest r_i·√(ρ_i/ρ) (the shortest Rayleigh time at density ρ).
double rayleigh_radius(const PourParams& p) {
    double radius = std::numeric_limits<double>::infinity();
    for (const PourSpecies& s : p.species()) {
        radius = std::min(radius, s.diameter / 2.0 * std::sqrt(s.density / p.density));
    }
    return p.is_blend() ? radius : p.diameter() / 2.0;
}

}  // namespace

std::string pour_script(const PourParams& p, double start_top) {
    const double d = p.diameter();
    const LiggghtsSeeds seeds = liggghts_seeds(p.seed);
    const bool periodic = p.sides == Sides::Periodic;
    std::map<std::string, std::string> values{
        {"what", p.is_blend() ? "spheres of " + std::to_string(p.species().size()) + " sizes"
                              : "equal spheres"},
        {"container_text",
         periodic ? "x and z periodic with period 1.25 m (boundary p f p), floor at y = "
                    "-0.625 m, no lid."
                  : "walls at x = +-0.625 m and z = +-0.625 m, floor at y = -0.625 m, no lid."},
        {"diameter_text",
         p.is_blend() ? "number-mean diameter d (m), the energy scale's" : "sphere diameter d (m)"},
        {"radius_text",
         p.is_blend() ? "smallest r_i sqrt(rho_i/rho) (m): time step, skin" : "d / 2 (m)"},
        {"boundary", periodic ? "p f p" : "f f f"},
        {"side_walls", periodic ? "# no side walls: x and z are periodic" : kSideWalls},
        {"sgmp_version", version()},
        {"count", std::to_string(p.count)},
        {"seed", std::to_string(p.seed)},
        {"diameter", format_number(d)},
        {"radius", format_number(rayleigh_radius(p))},
        {"density", format_number(p.density)},
        {"youngs_modulus", format_number(p.youngs_modulus)},
        {"poisson_ratio", format_number(p.poisson_ratio)},
        {"restitution", format_number(p.restitution)},
        {"friction", format_number(p.friction)},
        {"rolling_friction", format_number(p.rolling_friction)},
        {"tangential_damping", p.tangential_damping ? "on" : "off"},
        {"gravity", format_number(p.gravity)},
        {"timestep_fraction", format_number(p.timestep_fraction)},
        {"settle_threshold", format_number(p.settle_threshold)},
        {"check_time", format_number(p.check_time)},
        {"max_time", format_number(p.max_time)},
        {"cloud_fraction", format_number(p.cloud_fraction)},
        {"start_top", format_number(start_top)},
        {"domain_top", format_number(domain_top(start_top, d, p.is_blend()))},
        {"processor_grid", processor_grid(p)},
        {"seed_template", std::to_string(seeds.particle_template)},
        {"seed_distribution", std::to_string(seeds.distribution)},
        {"seed_insert", std::to_string(seeds.insertion)},
        {"arrangement", p.arrangement.value_or("")},
        // LIGGGHTS refuses E above 1e9 Pa in SI units unless told the particles are hard.
        {"hard_particles", p.youngs_modulus > 1e9 ? "hard_particles  yes" : "# E <= 1e9 Pa"},
    };
    values["insertion"] = insertion(p, seeds);
    // With periodic sides too the cloud fills the footprint: insert/pack keeps every sphere
    // wholly inside it (all_in), so two spheres at opposite faces are at least r_i + r_j
    // apart through the face as well.
    values["cloud_x_max"] = format_number(Container{}.x_max);
    values["cloud_z_max"] = format_number(Container{}.z_max);
    values["cloud_note"] =
        "the container's footprint (periodic too: all_in keeps spheres off the faces)";
    const std::string& start_template =
        embedded_template(p.arrangement ? "start-arrangement.in" : "start-cloud.in");
    values["start"] = fill_template(start_template, values);
    return fill_template(embedded_template("pour.in"), values);
}

}  // namespace sgmp::reference
