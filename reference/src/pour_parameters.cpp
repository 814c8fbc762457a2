#include "sgmp/reference/pour_parameters.hpp"

#include "sgmp/pack/size_mode_rows.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/reference/launcher.hpp"

namespace sgmp::reference {
namespace {

using Row = PourParameter;
using Check = std::function<void(const PourParams&, const PourCheckContext&)>;

/// A check of one real value: refused with "must be RULE" unless `ok(value)` and the value
/// is finite (inf passed "positive" and "above" rules).
template <class Member, class Ok>
Check require(const char* name, Member member, Ok ok, std::string rule) {
    return [=](const PourParams& p, const PourCheckContext&) {
        const double value = static_cast<double>(member(p));
        if (!ok(value) || !std::isfinite(value)) {
            throw ParameterError(name, format_number(value), "must be " + rule);
        }
    };
}

template <class Member>
Row number(const char* name, const char* group, Member member, std::string help, Check check) {
    return number_row<PourParams, PourCheckContext>(name, group, member, std::move(help),
                                                    std::move(check));
}

std::vector<Row> count_and_identity() {
    std::vector<Row> rows;
    const auto count = [](auto& p) -> auto& {
        return p.count;
    };
    Row n = whole_row<PourParams, PourCheckContext>(
        "count", "count", count,
        "Number of spheres N; d follows the sizing rule (N/3)(pi/6)d^3 = phi_target",
        require(
            "count", count, [](double v) { return v >= 1 && v <= static_cast<double>(kMaxCount); },
            "between 1 and " + std::to_string(kMaxCount)));
    n.rule = count_rule("", kMaxCount);
    n.required = true;
    rows.push_back(std::move(n));
    rows.push_back(number(
        "phi_target", "identity", [](auto& p) -> auto& { return p.phi_target; },
        "Target packing fraction phi* of the sizing rule",
        [](const PourParams& p, const PourCheckContext& c) {
            // Blends of several sizes pack denser than equal spheres can (size_modes.hpp).
            const bool blend = p.is_blend();
            require(
                "phi_target", [](const PourParams& q) { return q.phi_target; },
                [&](double v) { return v > 0.0 && v <= (blend ? 1.0 : kMaxPhiTarget); },
                blend ? "in (0, 1] for a blend" : "in (0, 0.74048]")(p, c);
        }));
    rows.push_back(number(
        "friction", "identity", [](auto& p) -> auto& { return p.friction; },
        "Sliding friction coefficient mu, particles and walls",
        require(
            "friction", [](const PourParams& p) { return p.friction; },
            [](double v) { return v >= 0.0 && v <= 10.0; }, "in [0, 10]")));
    rows.push_back(seed_row<PourParams, PourCheckContext>(
        "identity", "Seed of the LIGGGHTS insertion and the colour labels (integer)"));
    Row damping;
    damping.name = "tangential_damping";
    damping.group = "identity";
    damping.kind = ValueKind::Choice;
    damping.help =
        "Viscous damping of the tangential contact spring, on or off (off for exactly "
        "frictionless pours: at mu = 0 it still turns the spheres)";
    damping.rule = "must be one of on, off";
    damping.parse = [](PourParams& p, std::string_view text) {
        if (text != "on" && text != "off") {
            return false;
        }
        p.tangential_damping = text == "on";
        return true;
    };
    damping.format = [](const PourParams& p) {
        return std::string(p.tangential_damping ? "on" : "off");
    };
    damping.recorded = [](const PourParams&) { return false; };  // in contact_model
    rows.push_back(std::move(damping));
    return rows;
}

/// A row choosing a value of a name table (walls/periodic, number/volume/mass).
template <class Member, class Table>
Row choice(std::string name, Member member, Table table, std::string help) {
    return choice_row<PourParams, PourCheckContext>(std::move(name), "identity", member, table,
                                                    std::move(help));
}

/// The sizes of a blend, as `sgmp pack` takes them (size_modes.hpp), and the sides.
void add_sizes_and_sides(std::vector<Row>& rows) {
    Row modes = size_modes_row<PourParams, PourCheckContext>(
        "identity",
        "Particle sizes as relative-diameter:fraction[:density] items, as sgmp pack takes them "
        "(species 1, 2, ... in this order; fractions in --fraction-basis; densities relative, "
        "species 1 at --density); the pour holds the same counts and diameters as the pack",
        [](auto& p) -> auto& { return p.size_modes; });
    modes.recorded = [](const PourParams& p) { return p.is_blend(); };
    modes.check = [](const PourParams& p, const PourCheckContext&) {
        if (p.size_modes.empty()) {
            throw ParameterError("size_modes", "", "needs at least one mode");
        }
        // A pour tells species apart by their radius (one atom type for all).
        for (std::size_t i = 0; i < p.size_modes.size(); ++i) {
            for (std::size_t j = i + 1; j < p.size_modes.size(); ++j) {
                if (p.size_modes[i].relative_diameter == p.size_modes[j].relative_diameter) {
                    throw ParameterError("size_modes", size_modes_to_string(p.size_modes),
                                         "species " + std::to_string(i + 1) + " and " +
                                             std::to_string(j + 1) +
                                             " have one diameter; a pour needs each species "
                                             "of its own size");
                }
            }
        }
        if (p.is_blend() && p.arrangement) {
            throw ParameterError("size_modes", size_modes_to_string(p.size_modes),
                                 "a blend is poured from the cloud only (no --from-arrangement)");
        }
    };
    rows.push_back(std::move(modes));
    Row distribution = size_distribution_row<PourParams, PourCheckContext>(
        "identity",
        "Size distribution as sgmp pack takes it: a CSV file diameter,fraction[,density] or "
        "lognormal:MEDIAN:SIGMA[:CLASSES[:QLO:QHI]]",
        [](auto& p) -> auto& { return p.size_modes; },
        [](auto& p) -> auto& { return p.size_distribution; });
    // Unset (empty) reads back as the sizes of --size-modes.
    distribution.parse = [lognormal = distribution.parse](PourParams& p, std::string_view text) {
        if (text.empty()) {
            p.size_distribution.clear();
            return true;
        }
        return lognormal(p, text);
    };
    rows.push_back(std::move(distribution));
    Row basis = choice(
        "fraction_basis", [](auto& p) -> auto& { return p.fraction_basis; },
        [] { return fraction_bases(); },
        "What the fractions of --size-modes or --size-distribution are: number, volume or mass");
    basis.recorded = [](const PourParams& p) { return p.is_blend(); };
    basis.check = [](const PourParams& p, const PourCheckContext&) {
        (void)number_fractions(p.size_modes, p.fraction_basis);  // mass needs every density
    };
    rows.push_back(std::move(basis));
    Row sides = choice(
        "sides", [](auto& p) -> auto& { return p.sides; }, [] { return sides_names(); },
        "The container's lateral sides: walls, or periodic (LIGGGHTS boundary p f p: x and z "
        "periodic, the floor kept)");
    sides.recorded = [](const PourParams& p) { return p.sides != Sides::Walls; };
    sides.check = [](const PourParams& p, const PourCheckContext&) {
        if (p.sides != Sides::Periodic) {
            return;
        }
        double largest = 0.0;
        for (const PourSpecies& s : p.species()) {
            largest = std::max(largest, s.diameter);
        }
        const std::string rule = periodic_cell_rule(largest, kContainerSide);
        if (!rule.empty()) {
            throw ParameterError("sides", "periodic", rule);
        }
        if (p.arrangement) {
            throw ParameterError("sides", "periodic",
                                 "is poured from the cloud only (no --from-arrangement)");
        }
    };
    rows.push_back(std::move(sides));
}

void add_start(std::vector<Row>& rows) {
    Row cloud = number(
        "cloud_fraction", "start", [](auto& p) -> auto& { return p.cloud_fraction; },
        "Solid fraction of the starting cloud (sets its height)",
        require(
            "cloud_fraction", [](const PourParams& p) { return p.cloud_fraction; },
            [](double v) { return v > 0.0 && v <= 0.35; },
            "in (0, 0.35] (random insertion jams above)"));
    cloud.recorded = [](const PourParams& p) { return !p.arrangement; };
    rows.push_back(std::move(cloud));
    Row jitter = number(
        "start_jitter", "start", [](auto& p) -> auto& { return p.start_jitter; },
        "With --from-arrangement: move each sphere horizontally by a random offset up to this "
        "fraction of d (no overlaps created), which breaks symmetries DEM keeps for ever (a "
        "single column lands as a tower)",
        require(
            "start_jitter", [](const PourParams& p) { return p.start_jitter; },
            [](double v) { return v >= 0.0 && v <= 0.5; }, "in [0, 0.5]"));
    jitter.recorded = [](const PourParams& p) { return p.arrangement.has_value(); };
    rows.push_back(std::move(jitter));
}

void add_material(std::vector<Row>& rows) {
    const char* g = "material";
    rows.push_back(number(
        "restitution", g, [](auto& p) -> auto& { return p.restitution; },
        "Normal coefficient of restitution e",
        require(
            "restitution", [](const PourParams& p) { return p.restitution; },
            [](double v) { return v > 0.0 && v < 1.0; }, "in (0, 1)")));
    rows.push_back(number(
        "rolling_friction", g, [](auto& p) -> auto& { return p.rolling_friction; },
        "Rolling friction coefficient (constant directional torque)",
        require(
            "rolling_friction", [](const PourParams& p) { return p.rolling_friction; },
            [](double v) { return v >= 0.0 && v <= 1.0; }, "in [0, 1]")));
    Row youngs = number(
        "youngs_modulus", g, [](auto& p) -> auto& { return p.youngs_modulus; },
        "Young's modulus E in Pa (must exceed 5e6)",
        // LIGGGHTS refuses softer materials in SI units.
        require(
            "youngs_modulus", [](const PourParams& p) { return p.youngs_modulus; },
            [](double v) { return v > 5e6; }, "above 5e6 Pa"));
    youngs.header = "youngs_modulus_pa";
    rows.push_back(std::move(youngs));
    rows.push_back(number(
        "poisson_ratio", g, [](auto& p) -> auto& { return p.poisson_ratio; }, "Poisson's ratio nu",
        require(
            "poisson_ratio", [](const PourParams& p) { return p.poisson_ratio; },
            [](double v) { return v > 0.0 && v < 0.5; }, "in (0, 0.5)")));
    Row density = number(
        "density", g, [](auto& p) -> auto& { return p.density; }, "Particle density in kg/m^3",
        require(
            "density", [](const PourParams& p) { return p.density; },
            [](double v) { return v > 0.0; }, "positive"));
    density.header = "density_kg_m3";
    rows.push_back(std::move(density));
    Row gravity = number(
        "gravity", g, [](auto& p) -> auto& { return p.gravity; },
        "Gravitational acceleration in m/s^2 (along -Y)",
        require(
            "gravity", [](const PourParams& p) { return p.gravity; },
            [](double v) { return v > 0.0; }, "positive"));
    gravity.header = "gravity_m_s2";
    rows.push_back(std::move(gravity));
}

void add_numerics(std::vector<Row>& rows) {
    const char* g = "numerics";
    rows.push_back(number(
        "timestep_fraction", g, [](auto& p) -> auto& { return p.timestep_fraction; },
        "Time step as a fraction of the Rayleigh time",
        require(
            "timestep_fraction", [](const PourParams& p) { return p.timestep_fraction; },
            [](double v) { return v > 0.0 && v <= 0.5; }, "in (0, 0.5]")));
    rows.push_back(number(
        "settle_threshold", g, [](auto& p) -> auto& { return p.settle_threshold; },
        "Settled when the translational kinetic energy per particle stays below this times m g "
        "d at two consecutive checks",
        require(
            "settle_threshold", [](const PourParams& p) { return p.settle_threshold; },
            [](double v) { return v > 0.0; }, "positive")));
    Row check = number(
        "check_time", g, [](auto& p) -> auto& { return p.check_time; },
        "Simulated seconds between settling checks",
        require(
            "check_time", [](const PourParams& p) { return p.check_time; },
            [](double v) { return v > 0.0; }, "positive"));
    check.header = "check_time_s";
    rows.push_back(std::move(check));
    Row max_time = number(
        "max_time", g, [](auto& p) -> auto& { return p.max_time; },
        "Simulated seconds allowed before the pour counts as not settled (the step cap)",
        [](const PourParams& p, const PourCheckContext& c) {
            const auto time = [](const PourParams& q) { return q.max_time; };
            const std::string at = format_number(p.check_time);
            require(
                "max_time", time, [&](double v) { return v > p.check_time; },
                "longer than --check-time " + at)(p, c);
            require(
                "max_time", time, [&](double v) { return v / p.check_time <= 1e6; },
                "at most 10^6 settling checks (--max-time / --check-time " + at + ")")(p, c);
        });
    max_time.recorded = [](const PourParams&) { return false; };  // as step_cap
    rows.push_back(std::move(max_time));
}

void add_parallel(std::vector<Row>& rows) {
    Row ranks = whole_row<PourParams, PourCheckContext>(
        "ranks", "parallel", [](auto& p) -> auto& { return p.ranks; },
        "MPI ranks; above 1 runs LIGGGHTS under --launcher with a processor grid chosen from "
        "the container (PY = 1: x and z split, never the fall)",
        require(
            "ranks", [](const PourParams& p) { return p.ranks; },
            [](double v) { return v >= 1 && v <= 64; }, "between 1 and 64"));
    rows.push_back(std::move(ranks));
    Row processors;
    processors.name = "processors";
    processors.group = "parallel";
    processors.kind = ValueKind::Text;
    processors.help =
        "LIGGGHTS processor grid PX,PY,PZ (PX*PY*PZ = --ranks; default: chosen from the "
        "container, y never split)";
    processors.rule = "must be PX,PY,PZ";
    processors.parse = [](PourParams& p, std::string_view text) {
        p.processors = std::string(text);
        return true;
    };
    processors.format = [](const PourParams& p) { return p.processors; };
    processors.check = [](const PourParams& p, const PourCheckContext&) {
        if (p.processors.empty()) {
            return;
        }
        const auto grid = parse_processor_grid(p.processors);
        if (!grid || (*grid)[0] * (*grid)[1] * (*grid)[2] != p.ranks) {
            throw ParameterError("processors", p.processors,
                                 "must be PX,PY,PZ, whole numbers >= 1 with PX*PY*PZ = ranks " +
                                     std::to_string(p.ranks));
        }
    };
    processors.recorded = [](const PourParams&) { return false; };  // as processor_grid
    processors.unset_by_default = true;
    rows.push_back(std::move(processors));
}

std::vector<Row> make_rows() {
    std::vector<Row> rows = count_and_identity();
    add_sizes_and_sides(rows);
    add_start(rows);
    add_material(rows);
    add_numerics(rows);
    add_parallel(rows);
    fill_defaults(rows);
    return rows;
}

}  // namespace

const std::vector<PourParameter>& pour_parameters() {
    static const std::vector<PourParameter> rows = make_rows();
    return rows;
}

void record_pour_parameters(const PourParams& params, std::string_view group, Metadata& metadata) {
    record_rows(pour_parameters(), params, group, metadata);
}

void PourParams::validate() const {
    check_rows(pour_parameters(), *this, "", PourCheckContext{});
}

}  // namespace sgmp::reference
