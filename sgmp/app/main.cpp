// sgmp — packs spheres with the Spin Gap Move Protocol.
//   sgmp pack    --count N --arrangement A --seed S --out FILE [protocol options] [--force]
//   sgmp arrange --count N --arrangement A --seed S --out FILE [--force]
// A thin front end: parses options, calls the engine, writes the pack atomically.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "batch_command.hpp"
#include "config_file.hpp"
#include "convert_command.hpp"
#include "render_command.hpp"
#include "sgmp/cli/progress_line.hpp"
#include "sgmp/cli/run_main.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/engine/pack_checks.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"
#include "sgmp/pack/version.hpp"

namespace {

using namespace sgmp;
using namespace sgmp::engine;

/// Raw option values as typed; turned into a PackRequest (with one-line errors) later.
struct Options {
    long long count = 0;
    std::string arrangement;
    std::uint64_t seed = 1;
    std::string out;
    bool force = false;
    double phi_target = kThesisPhiTarget;
    std::string size_modes = "1:1";
    double circle_factor = 50.0;
    int sweep_positions = 120;
    std::string sweep_stages;
    int lower_neighbours = 10;
    std::string gap = "largest";
    std::string fall = "exact";
    double fall_step = 0.001;
    std::string contact = "none";
    double momentum = 0.0;
    std::string walls = "fix";
    long stall_moves = 50;
    long max_moves = 100000;
    std::string relax = "none";
    RelaxParams relax_params;
};

using cli::UsageError;

void add_common(CLI::App& app, Options& o) {
    app.add_option("--count", o.count, "number of particles N (1 to 10000000)")->required();
    app.add_option("--arrangement", o.arrangement,
                   "starting arrangement: single-column, small-dense, large-dense, loose-random")
        ->required();
    app.add_option("--seed", o.seed,
                   "random seed (colours, loose-random positions, random choices)")
        ->capture_default_str()
        ->check([](const std::string& text) { return sgmp::seed_rule(text); });
    app.add_option("--out", o.out, "output pack file (extended XYZ; .gz compresses)")->required();
    app.add_flag("--force", o.force, "overwrite an existing output file");
    app.add_option("--phi-target", o.phi_target,
                   "target packing fraction phi* in (0, 0.74048]; sets the diameter by "
                   "(N/3)(pi/6)d^3 = phi*")
        ->capture_default_str();
    app.add_option("--size-modes", o.size_modes,
                   "particle sizes as relative-diameter:number-fraction pairs, e.g. 1:0.7,0.5:0.3; "
                   "the scale s solves (N/3)(pi/6) sum f_i (a_i s)^3 = phi*")
        ->capture_default_str();
}

void add_protocol(CLI::App& app, Options& o) {
    app.add_option("--circle-factor", o.circle_factor,
                   "circle factor F > 1: sweep radius = d/F (length units of the control volume)")
        ->capture_default_str();
    app.add_option("--sweep-positions", o.sweep_positions,
                   "positions tested on the sweep circle (>= 3; 120 = every 3 degrees)")
        ->capture_default_str();
    app.add_option("--sweep-stages", o.sweep_stages,
                   "multi-stage sweep, increasing counts such as 8,120,720: a stage is tried "
                   "only when the previous one found no free position (overrides "
                   "--sweep-positions)")
        ->check([](const std::string& text) {
            return text.empty() ? "must list at least one count, e.g. 8,120,720" : "";
        });
    app.add_option("--lower-neighbours", o.lower_neighbours,
                   "size of the lower columnar neighbour list (>= 1; recorded, does not change "
                   "results: the fall scans the whole column below)")
        ->capture_default_str();
    app.add_option("--gap", o.gap, "free arc to move toward: largest | random")
        ->capture_default_str();
    app.add_option("--fall", o.fall,
                   "fall mode: exact (jump to the first contact; ends touching) | step (thesis "
                   "steps of --fall-step; ends less than one step above the contact)")
        ->capture_default_str();
    app.add_option("--fall-step", o.fall_step,
                   "downward increment of the step fall, 0 < step < d (control-volume units)")
        ->capture_default_str();
    app.add_option("--contact", o.contact,
                   "contact model for resting particles: none | settle (drop onto the support "
                   "and roll down over it to a second contact) | roll (roll on down to a stable "
                   "rest on three spheres, or the floor or a wall)")
        ->capture_default_str();
    app.add_option("--momentum", o.momentum,
                   "momentum weight m in [0, 1): move toward (1-m)*bisector + m*previous move")
        ->capture_default_str();
    app.add_option("--walls", o.walls,
                   "side walls: fix (a particle a move brings to a wall stops there, thesis) | "
                   "block (walls are obstacles like particles)")
        ->capture_default_str();
    app.add_option("--stall-moves", o.stall_moves,
                   "a particle making this many consecutive moves without falling rests (>= 1)")
        ->capture_default_str();
    app.add_option("--max-moves", o.max_moves,
                   "bound on sweep-and-move cycles per particle (>= 1); a particle reaching it "
                   "rests where its last fall left it")
        ->capture_default_str();
}

void add_relax(CLI::App& app, Options& o) {
    RelaxParams& r = o.relax_params;
    app.add_option("--relax", o.relax,
                   "after deposition: none | frictionless (relax the whole pack under gravity "
                   "to an equilibrium of frictionless soft spheres by FIRE energy "
                   "minimisation, then finish it as hard spheres) | frictional (the same "
                   "with Coulomb friction: tangential springs capped at mu*F_n)")
        ->capture_default_str();
    app.add_option("--relax-stiffness", r.stiffness,
                   "contact stiffness k of the first relaxation stage in m*g/d (a contact "
                   "carrying one weight m*g overlaps by d/k)")
        ->capture_default_str();
    app.add_option("--relax-stiffness-factor", r.stiffness_factor,
                   "each later relaxation stage multiplies the stiffness by this factor")
        ->capture_default_str();
    app.add_option("--relax-stages", r.stages, "number of stiffness stages (1 to 10)")
        ->capture_default_str();
    app.add_option("--relax-shell", r.shell,
                   "contact shell s in [0, 0.01]: the soft spheres are (1+s) times the real "
                   "ones, so soft contacts end as gaps of at most s*(ri+rj)")
        ->capture_default_str();
    app.add_option("--relax-force-tolerance", r.force_tolerance,
                   "a stage has converged when no sphere feels a net force above this, in m*g "
                   "(m the mass of a sphere of relative size 1)")
        ->capture_default_str();
    app.add_option("--relax-time", r.time,
                   "bound on the first stage's simulated time, in units of sqrt(H/g) (H: the "
                   "pack's height above the floor)")
        ->capture_default_str();
    app.add_option("--relax-crossings", r.crossings,
                   "bound on each later stage's steps, in units of H/d (the elastic relaxation "
                   "crosses the pack's height); the pack records the force left "
                   "(relax_force_max)")
        ->capture_default_str();
    app.add_option("--relax-friction", r.friction,
                   "sliding friction mu of --relax frictional (pairs and walls), in [0, 10]")
        ->capture_default_str();
    app.add_option("--relax-tangential-ratio", r.tangential_ratio,
                   "tangential over normal contact stiffness of --relax frictional, in (0, 1]")
        ->capture_default_str();
}

template <class T>
T parse_choice(std::optional<T> parsed, const std::string& option, const std::string& value,
               const std::string& choices) {
    if (!parsed) {
        throw UsageError("--" + option + " " + value + ": must be one of " + choices);
    }
    return *parsed;
}

PackRequest to_request(const Options& o) {
    if (o.count < 1 || o.count > static_cast<long long>(kMaxCount)) {
        throw ParameterError("count", std::to_string(o.count),
                             "must be between 1 and " + std::to_string(kMaxCount));
    }
    PackRequest request;
    request.count = static_cast<std::size_t>(o.count);
    request.arrangement = parse_choice(parse_arrangement(o.arrangement), "arrangement",
                                       o.arrangement, std::string(arrangement_names()));
    request.seed = o.seed;
    request.phi_target = o.phi_target;
    const auto modes = parse_size_modes(o.size_modes);
    if (!modes) {
        throw UsageError("--size-modes " + o.size_modes +
                         ": must be positive diameter:fraction pairs, e.g. 1:0.7,0.5:0.3");
    }
    request.size_modes = *modes;
    ProtocolParams& p = request.protocol;
    p.circle_factor = o.circle_factor;
    p.sweep_stages = {o.sweep_positions};
    if (!o.sweep_stages.empty()) {
        const auto stages = parse_stages(o.sweep_stages);
        if (!stages) {
            throw UsageError("--sweep-stages " + o.sweep_stages +
                             ": must be comma-separated whole numbers, e.g. 8,120,720");
        }
        p.sweep_stages = *stages;
    }
    p.lower_neighbours = o.lower_neighbours;
    p.gap = parse_choice(parse_gap_rule(o.gap), "gap", o.gap, gap_rules().choices());
    p.fall = parse_choice(parse_fall_mode(o.fall), "fall", o.fall, fall_modes().choices());
    p.fall_step = o.fall_step;
    p.contact = parse_choice(parse_contact_model(o.contact), "contact", o.contact,
                             contact_models().choices());
    p.momentum = o.momentum;
    p.walls = parse_choice(parse_wall_rule(o.walls), "walls", o.walls, wall_rules().choices());
    p.stall_moves = o.stall_moves;
    p.max_moves = o.max_moves;
    request.relax = o.relax_params;
    request.relax.mode =
        parse_choice(parse_relax_mode(o.relax), "relax", o.relax, relax_modes().choices());
    validate(request);
    return request;
}

/// `--config FILE` (config_file.hpp): its options are placed before the command line's.
std::vector<std::string> expand_config(std::vector<std::string> args) {
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string path;
        if (args[i] == "--config" && i + 1 < args.size()) {
            path = args[i + 1];
        } else if (args[i].rfind("--config=", 0) == 0) {
            path = args[i].substr(9);
        } else {
            continue;
        }
        if (!std::filesystem::is_regular_file(path)) {
            throw UsageError("--config " + path + ": must name a readable file");
        }
        std::ifstream in(path);
        try {
            const auto injected = sgmp::app::config_arguments(in, args.front());
            args.insert(args.begin() + 1, injected.begin(), injected.end());
        } catch (const std::invalid_argument& e) {
            throw UsageError("--config " + path + ": " + e.what());
        }
        return args;
    }
    return args;
}

/// --out must be writable before any work starts (a usage error, exit 2).
void check_out(const Options& o) {
    try {
        check_writable(o.out, o.force);
    } catch (const std::runtime_error& e) {
        throw UsageError(std::string("--out ") + e.what());
    }
}

int run_pack(const Options& o) {
    const PackRequest request = to_request(o);
    check_out(o);
    // Progress once a run passes one second.
    cli::ProgressLine progress(false, std::chrono::seconds(5), std::chrono::seconds(1));
    const Pack pack = make_pack(request, [&](std::size_t done, std::size_t total) {
        progress.update("sgmp: " + std::to_string(done) + " / " + std::to_string(total) +
                        " particles dropped (" +
                        std::to_string(static_cast<long>(progress.seconds())) + " s)");
    });
    const double seconds = progress.seconds();
    progress.finish();
    write_pack_file(o.out, pack, o.force);
    const double d = *pack.metadata.get_number("diameter");
    const PackCheck check = check_pack(pack.particles, Container{}, 1e-9 * d, 0.0);
    std::printf(
        "sgmp: packed %zu particles, %s, d=%.6g, %.3f s, phi(control volume)=%.4f, "
        "overlaps=%zu -> %s\n",
        pack.particles.size(), std::string(to_string(request.arrangement)).c_str(), d, seconds,
        packing_fraction(pack, control_volume()), check.overlaps, o.out.c_str());
    return 0;
}

int run_arrange(const Options& o) {
    const PackRequest request = to_request(o);
    check_out(o);
    const Pack pack = make_start_pack(request);
    write_pack_file(o.out, pack, o.force);
    std::printf("sgmp: arranged %zu particles, %s, d=%.6g, start height %.4f -> %s\n",
                pack.particles.size(), std::string(to_string(request.arrangement)).c_str(),
                *pack.metadata.get_number("diameter"), *pack.metadata.get_number("start_height"),
                o.out.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"sgmp " + std::string(sgmp::version()) +
                 " — sphere packs by the Spin Gap Move Protocol (Y up; container x, z in "
                 "[-0.625, 0.625], floor y = -0.625, no lid; lengths in control-volume sides)"};
    app.name("sgmp");
    // The bare version, as pack headers record it (scripts compare the two).
    app.set_version_flag("--version", std::string(sgmp::version()));
    app.require_subcommand(1);
    // A repeated option keeps its last value, so the command line overrides a --config file.
    app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    Options pack_options;
    CLI::App* pack = app.add_subcommand("pack",
                                        "drop the particles of a starting arrangement "
                                        "with the protocol and write the pack");
    add_common(*pack, pack_options);
    add_protocol(*pack, pack_options);
    add_relax(*pack, pack_options);
    std::string config_file;
    pack->add_option("--config", config_file,
                     "read options from a TOML/INI file of 'option = value' lines (e.g. count = "
                     "1002); options given on the command line win");
    Options arrange_options;
    CLI::App* arrange = app.add_subcommand(
        "arrange", "write the starting arrangement itself (positions before packing)");
    add_common(*arrange, arrange_options);
    arrange->add_option("--config", config_file,
                        "read options from a TOML/INI file of 'option = value' lines; options "
                        "given on the command line win");
    CLI::App* convert = sgmp::app::register_convert(app);
    const auto render = sgmp::app::register_render(app);
    sgmp::app::BatchCommand batch(app);
    const auto parse = [&] {
        std::vector<std::string> args(argv + 1, argv + argc);
        args = expand_config(std::move(args));
        std::reverse(args.begin(), args.end());  // CLI11 takes the arguments reversed
        app.parse(args);
    };
    return cli::run_main("sgmp", app, parse, [&] {
        install_interrupt_handler("sgmp");
        if (convert->parsed()) {
            return sgmp::app::run_convert();
        }
        if (render.command->parsed()) {
            return render.run();
        }
        if (batch.parsed()) {
            return batch.run();
        }
        return pack->parsed() ? run_pack(pack_options) : run_arrange(arrange_options);
    });
}
