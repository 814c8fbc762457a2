#include "sgmp/reference/input_script.hpp"

#include <stdexcept>

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

double domain_top(double start_top, double diameter) {
    // Spheres thrown up in the first collisions rarely rise more than a few diameters;
    // a sphere leaving the box would stop the run ("lost atoms"), never pass silently.
    return start_top + 0.25 * (start_top + 0.625) + 4.0 * diameter;
}

std::string processor_grid(const PourParams& p) {
    const Container c;
    const auto grid = p.processors.empty()
                          ? choose_processor_grid(p.ranks, c.x_max - c.x_min, c.z_max - c.z_min)
                          : parse_processor_grid(p.processors).value();
    return std::to_string(grid[0]) + " " + std::to_string(grid[1]) + " " + std::to_string(grid[2]);
}

std::string pour_script(const PourParams& p, double start_top) {
    const double d = p.diameter();
    const LiggghtsSeeds seeds = liggghts_seeds(p.seed);
    std::map<std::string, std::string> values{
        {"sgmp_version", version()},
        {"count", std::to_string(p.count)},
        {"seed", std::to_string(p.seed)},
        {"diameter", format_number(d)},
        {"radius", format_number(d / 2.0)},
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
        {"domain_top", format_number(domain_top(start_top, d))},
        {"processor_grid", processor_grid(p)},
        {"seed_template", std::to_string(seeds.particle_template)},
        {"seed_distribution", std::to_string(seeds.distribution)},
        {"seed_insert", std::to_string(seeds.insertion)},
        {"arrangement", p.arrangement.value_or("")},
        // LIGGGHTS refuses E above 1e9 Pa in SI units unless told the particles are hard.
        {"hard_particles", p.youngs_modulus > 1e9 ? "hard_particles  yes" : "# E <= 1e9 Pa"},
    };
    const std::string& start_template =
        embedded_template(p.arrangement ? "start-arrangement.in" : "start-cloud.in");
    values["start"] = fill_template(start_template, values);
    return fill_template(embedded_template("pour.in"), values);
}

}  // namespace sgmp::reference
