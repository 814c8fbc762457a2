#include "sgmp/engine/pack_parameters.hpp"

#include "pack_parameter_rows.hpp"

#include "sgmp/pack/size_mode_rows.hpp"

#include "sgmp/engine/hard_sphere_settle.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/parameter_error.hpp"

namespace sgmp::engine {
namespace {

using namespace pack_rows;

bool is_blend(const PackRequest& r) {
    return std::any_of(r.size_modes.begin(), r.size_modes.end(), [&](const SizeMode& m) {
        return m.relative_diameter != r.size_modes.front().relative_diameter;
    });
}

void check_phi_target(const PackRequest& r, const PackCheckContext&) {
    const double phi = r.phi_target;
    if (!is_blend(r) && (!(phi > 0.0) || !(phi <= kMaxPhiTarget))) {
        refuse("phi_target", format_number(phi),
               "must be in (0, 0.74048] (the densest packing of equal spheres)");
    }
    if (is_blend(r) && (!(phi > 0.0) || !(phi < 1.0))) {
        refuse("phi_target", format_number(phi), "must be in (0, 1) for a blend of several sizes");
    }
    if (phi < 1e-3) {
        // Below this the sizing rule gives spheres smaller than the default fall step.
        refuse("phi_target", format_number(phi),
               "must be at least 0.001 (smaller targets give vanishing diameters)");
    }
}

void check_size_modes(const PackRequest& r, const PackCheckContext&) {
    if (r.size_modes.empty()) {
        refuse("size_modes", "", "needs at least one mode");
    }
    double total = 0.0;
    for (const SizeMode& m : r.size_modes) {
        if (!(m.relative_diameter > 0.0) || !(m.fraction >= 0.0) ||
            !std::isfinite(m.relative_diameter) || !std::isfinite(m.fraction) ||
            (m.density && !(*m.density > 0.0 && std::isfinite(*m.density)))) {
            refuse("size_modes", size_modes_to_string(r.size_modes),
                   "relative diameters and densities must be positive, fractions not negative");
        }
        total += m.fraction;
    }
    if (!(total > 0.0)) {
        refuse("size_modes", size_modes_to_string(r.size_modes),
               "every fraction is 0: at least one must be positive");
    }
}

void check_sweep_stages(const PackRequest& r, const PackCheckContext&) {
    const std::vector<int>& stages = r.protocol.sweep_stages;
    if (stages.empty()) {
        refuse("sweep_stages", "", "needs at least one stage");
    }
    for (std::size_t i = 0; i < stages.size(); ++i) {
        if (stages[i] < 3 || stages[i] > kMaxSweepPositions) {
            refuse(stages.size() == 1 ? "sweep_positions" : "sweep_stages",
                   stages_to_string(stages), "every stage needs 3 to 1000000 sweep positions");
        }
        if (i > 0 && stages[i] <= stages[i - 1]) {
            refuse("sweep_stages", stages_to_string(stages),
                   "stages must have strictly increasing position counts");
        }
    }
}

void check_fall_step(const PackRequest& r, const PackCheckContext& context) {
    // The step fall needs a step below the smallest diameter; the exact fall ignores it.
    const ProtocolParams& p = r.protocol;
    if (!(p.fall_step > 0.0) || !std::isfinite(p.fall_step) ||
        (p.fall == FallMode::Step && !(p.fall_step < context.smallest_diameter))) {
        refuse("fall_step", format_number(p.fall_step),
               "must be greater than 0 and less than the diameter " +
                   format_number(context.smallest_diameter));
    }
}

/// The particle count's row: required, 1 to kMaxCount.
Row count_row() {
    Row count = whole(
        "count", "count", [](auto& r) -> auto& { return r.count; },
        "number of particles N (1 to " + std::to_string(kMaxCount) + ")",
        [](const PackRequest& r, const PackCheckContext&) {
            if (r.count < 1 || r.count > kMaxCount) {
                refuse("count", std::to_string(r.count),
                       "must be between 1 and " + std::to_string(kMaxCount));
            }
        });
    count.rule = "must be a whole number between 1 and " + std::to_string(kMaxCount);
    count.required = true;
    return count;
}

/// The starting arrangement's row: required, one of the four.
Row arrangement_row() {
    Row arrangement;
    arrangement.name = "arrangement";
    arrangement.group = "request";
    arrangement.kind = ValueKind::Choice;
    arrangement.help =
        "starting arrangement: single-column, small-dense, large-dense, loose-random";
    arrangement.rule = "must be one of " + std::string(arrangement_names());
    arrangement.parse = [](PackRequest& r, std::string_view text) {
        const auto parsed = parse_arrangement(text);
        if (parsed) {
            r.arrangement = *parsed;
        }
        return parsed.has_value();
    };
    arrangement.format = [](const PackRequest& r) { return std::string(to_string(r.arrangement)); };
    arrangement.required = true;
    return arrangement;
}

/// The largest diameter's row: a physical length, recorded when given.
Row largest_diameter_row() {
    Row largest;
    largest.name = "largest_diameter";
    largest.group = "request";
    largest.kind = ValueKind::Text;
    largest.help =
        "the largest species' diameter in a physical unit, e.g. '200 um' (set by a "
        "--size-distribution CSV whose diameter column names its unit, diameter_um); sgmp "
        "convert --length-unit then needs no --length-scale";
    largest.rule = "must be 'VALUE UNIT', VALUE > 0, UNIT one of " + std::string(length_units());
    largest.parse = [](PackRequest& r, std::string_view text) {
        if (!parse_physical_length(text)) {
            return false;
        }
        r.largest_diameter = std::string(text);
        return true;
    };
    largest.format = [](const PackRequest& r) { return r.largest_diameter; };
    largest.recorded = [](const PackRequest& r) { return !r.largest_diameter.empty(); };
    largest.unset_by_default = true;
    return largest;
}

/// The rows of the particles' sizes: modes or a distribution, the largest diameter, the
/// fractions' basis and a blend's drop order.
void add_size_rows(std::vector<Row>& rows) {
    Row modes = size_modes_row<PackRequest, PackCheckContext>(
        "request",
        "particle sizes as relative-diameter:fraction[:density] items, e.g. 1:0.7,0.5:0.3 "
        "(species 1, 2, ... in this order; fractions in --fraction-basis); the scale s solves "
        "(N/3)(pi/6) sum n_i (a_i s)^3 = phi* with number fractions n_i",
        [](auto& r) -> auto& { return r.size_modes; });
    modes.check = check_size_modes;
    rows.push_back(std::move(modes));
    rows.push_back(size_distribution_row<PackRequest, PackCheckContext>(
        "request",
        "size distribution as a CSV file: header diameter,fraction[,density], one row per "
        "species (diameters in any unit; species 1, 2, ... in file order); or "
        "lognormal:MEDIAN:SIGMA[:CLASSES[:QLO:QHI]]: ln D normal with that median and sd, cut "
        "at the quantiles QLO, QHI (default 0.01, 0.99) into CLASSES (default 10) species of "
        "equal fraction, each of its class's median diameter",
        [](auto& r) -> auto& { return r.size_modes; },
        [](auto& r) -> auto& { return r.size_distribution; }));
    rows.push_back(largest_diameter_row());
    Row basis = choice(
        "fraction_basis", "request", [](auto& r) -> auto& { return r.fraction_basis; },
        [] { return fraction_bases(); },
        "what the fractions of --size-modes or --size-distribution are: number, volume or mass "
        "(mass needs densities)");
    basis.recorded = [](const PackRequest& r) {
        return r.fraction_basis != FractionBasis::Number || !r.size_distribution.empty();
    };
    basis.check = [](const PackRequest& r, const PackCheckContext&) {
        (void)number_fractions(r.size_modes, r.fraction_basis);  // mass needs every density
    };
    rows.push_back(std::move(basis));
    Row order = choice(
        "drop_order", "request", [](auto& r) -> auto& { return r.drop_order; },
        [] { return drop_orders(); },
        "the order a blend's particles drop in: stratified (each species within one particle of "
        "its share in every run of drops from the first, so every height gets the blend) or "
        "shuffled (a random permutation)");
    order.recorded = [](const PackRequest& r) { return r.size_modes.size() > 1; };
    rows.push_back(std::move(order));
}

/// The request's rows: count, target, arrangement, seed, sizes and sides.
std::vector<Row> count_and_request_rows() {
    std::vector<Row> rows;
    rows.push_back(count_row());
    rows.push_back(number(
        "phi_target", "request", [](auto& r) -> auto& { return r.phi_target; },
        "target packing fraction phi* in (0, 0.74048] for equal spheres, (0, 1) for a blend of "
        "several sizes; sets the diameter by (N/3)(pi/6)d^3 = phi*",
        check_phi_target));
    rows.push_back(arrangement_row());
    rows.push_back(seed_row<PackRequest, PackCheckContext>(
        "request", "random seed (colours, loose-random positions, random choices)"));
    add_size_rows(rows);
    Row sides = choice(
        "sides", "request", [](auto& r) -> auto& { return r.sides; }, [] { return sides_names(); },
        "the container's lateral sides: walls (the thesis') or periodic (x and z periodic, the "
        "floor kept; the largest sphere must fit the 1.25-wide cell 4 times across)");
    sides.recorded = [](const PackRequest& r) { return r.sides != Sides::Walls; };
    rows.push_back(std::move(sides));
    return rows;
}

void add_protocol_rows(std::vector<Row>& rows) {
    const std::string g = "protocol";
    rows.push_back(number(
        "circle_factor", g, [](auto& r) -> auto& { return r.protocol.circle_factor; },
        "circle factor F > 1: sweep radius = d/F (length units of the control volume)",
        [](const PackRequest& r, const PackCheckContext&) {
            const double f = r.protocol.circle_factor;
            if (!(f > 1.0) || !std::isfinite(f)) {
                refuse("circle_factor", format_number(f),
                       "must be a number greater than 1 (sweep radius = d / factor)");
            }
        }));
    Row positions = whole("sweep_positions", g,
                          [](auto& r) -> auto& { return r.protocol.sweep_stages.front(); },
                          "positions tested on the sweep circle (>= 3; 120 = every 3 degrees)", {});
    positions.parse = [](PackRequest& r, std::string_view text) {
        const auto n = parse_whole<int>(text);
        if (n) {
            r.protocol.sweep_stages = {*n};  // sweep_stages, later in the table, overrides it
        }
        return n.has_value();
    };
    positions.recorded = [](const PackRequest&) { return false; };  // as sweep_stages
    rows.push_back(std::move(positions));
    Row stages;
    stages.name = "sweep_stages";
    stages.group = g;
    stages.kind = ValueKind::List;
    stages.help =
        "multi-stage sweep, increasing counts such as 8,120,720: a stage is tried only when the "
        "previous one found no free position (overrides --sweep-positions)";
    stages.rule = "must be comma-separated whole numbers, e.g. 8,120,720";
    stages.parse = [](PackRequest& r, std::string_view text) {
        auto parsed = parse_stages(text);
        if (parsed) {
            r.protocol.sweep_stages = std::move(*parsed);
        }
        return parsed.has_value();
    };
    stages.format = [](const PackRequest& r) { return stages_to_string(r.protocol.sweep_stages); };
    stages.check = check_sweep_stages;
    stages.unset_by_default = true;
    rows.push_back(std::move(stages));
    rows.push_back(whole(
        "lower_neighbours", g, [](auto& r) -> auto& { return r.protocol.lower_neighbours; },
        "size of the lower columnar neighbour list (>= 1; recorded, does not change results: "
        "the fall scans the whole column below)",
        at_least_one("lower_neighbours",
                     [](const PackRequest& r) { return r.protocol.lower_neighbours; })));
    rows.push_back(choice(
        "gap", g, [](auto& r) -> auto& { return r.protocol.gap; }, [] { return gap_rules(); },
        "free arc to move toward: largest | random"));
    rows.push_back(choice(
        "fall", g, [](auto& r) -> auto& { return r.protocol.fall; }, [] { return fall_modes(); },
        "fall mode: exact (jump to the first contact; ends touching) | step (thesis steps of "
        "--fall-step; ends less than one step above the contact)"));
    rows.push_back(number(
        "fall_step", g, [](auto& r) -> auto& { return r.protocol.fall_step; },
        "downward increment of the step fall, 0 < step < d (control-volume units)",
        check_fall_step));
    rows.push_back(choice(
        "contact", g, [](auto& r) -> auto& { return r.protocol.contact; },
        [] { return contact_models(); },
        "contact model for resting particles: none | settle (drop onto the support and roll "
        "down over it to a second contact) | roll (roll on down to a stable rest on three "
        "spheres, or the floor or a wall)"));
    rows.push_back(number(
        "momentum", g, [](auto& r) -> auto& { return r.protocol.momentum; },
        "momentum weight m in [0, 1): move toward (1-m)*bisector + m*previous move",
        [](const PackRequest& r, const PackCheckContext&) {
            const double m = r.protocol.momentum;
            if (!(m >= 0.0) || !(m < 1.0)) {
                refuse("momentum", format_number(m), "must be in [0, 1)");
            }
        }));
    rows.push_back(choice(
        "walls", g, [](auto& r) -> auto& { return r.protocol.walls; }, [] { return wall_rules(); },
        "side walls: fix (a particle a move brings to a wall stops there, thesis) | block (walls "
        "are obstacles like particles)"));
    rows.push_back(whole(
        "stall_moves", g, [](auto& r) -> auto& { return r.protocol.stall_moves; },
        "a particle making this many consecutive moves without falling rests (>= 1)",
        at_least_one("stall_moves", [](const PackRequest& r) { return r.protocol.stall_moves; })));
    rows.push_back(whole(
        "max_moves", g, [](auto& r) -> auto& { return r.protocol.max_moves; },
        "bound on sweep-and-move cycles per particle (>= 1); a particle reaching it rests where "
        "its last fall left it",
        at_least_one("max_moves", [](const PackRequest& r) { return r.protocol.max_moves; })));
}

std::vector<Row> make_rows() {
    std::vector<Row> rows = count_and_request_rows();
    add_protocol_rows(rows);
    add_relax_rows(rows);
    fill_defaults(rows);
    return rows;
}

}  // namespace

const std::vector<PackParameter>& pack_parameters() {
    static const std::vector<PackParameter> rows = make_rows();
    return rows;
}

const PackParameter* find_pack_parameter(std::string_view name) {
    return find_row(pack_parameters(), name);
}

void set_pack_parameter(PackRequest& request, std::string_view name, std::string_view text) {
    const PackParameter* row = find_pack_parameter(name);
    if (row == nullptr) {
        throw ParameterError(std::string(name), std::string(text), "is not a pack parameter");
    }
    if (!row->parse(request, text)) {
        throw ParameterError(row->name, std::string(text), row->rule);
    }
}

void record_pack_parameters(const PackRequest& request, std::string_view group,
                            Metadata& metadata) {
    record_rows(pack_parameters(), request, group, metadata);
}

void check_pack_parameters(const PackRequest& request, std::string_view group,
                           const PackCheckContext& context) {
    check_rows(pack_parameters(), request, group, context);
}

}  // namespace sgmp::engine
