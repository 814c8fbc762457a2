// sgmp — packs spheres with the Spin Gap Move Protocol.
//   sgmp pack    --count N --arrangement A --seed S --out FILE [protocol options] [--force]
//   sgmp arrange --count N --arrangement A --seed S --out FILE [--force]
// A thin front end: parses options, calls the engine, writes the pack atomically.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "batch_command.hpp"
#include "config_file.hpp"
#include "convert_command.hpp"
#include "render_command.hpp"
#include "sgmp/cli/progress_line.hpp"
#include "sgmp/cli/run_main.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/pack_overlaps.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"
#include "sgmp/pack/version.hpp"

namespace {

using namespace sgmp;
using namespace sgmp::engine;

/// The command line's values. Options bind straight to the request (its defaults are the
/// library's, shown by --help); only the values that need a rule across options stay raw.
struct Options {
    long long count = 0;
    std::string out;
    bool force = false;
    bool keep_uncertified = false;
    PackRequest request;
    /// --sweep-positions is one stage; --sweep-stages, when given, overrides it.
    int sweep_positions = ProtocolParams{}.sweep_stages.front();
    std::optional<std::vector<int>> sweep_stages;
    /// --size-distribution FILE, read into the request's modes by to_request.
    std::string size_distribution;
    CLI::Option* size_modes_option = nullptr;
    /// The first value refused while parsing; reported once parsing is done (so --help
    /// and missing options come first, then the count's range, as for the other rules).
    std::optional<std::string> refused;
};

using cli::UsageError;

/// An option parsed by `parse` straight into `target`; a value it refuses (nullopt) is
/// kept in `refused` as "NAME VALUE: RULE".
template <class T, class Parse>
CLI::Option* add_parsed(CLI::App& app, Options& o, const std::string& name, T& target, Parse parse,
                        const std::string& rule, const std::string& help) {
    return app.add_option_function<std::string>(
        name,
        [&o, &target, parse, name, rule](const std::string& text) {
            const auto parsed = parse(text);
            if (parsed) {
                target = *parsed;
            } else if (!o.refused) {
                o.refused = name + " " + text + ": " + rule;
            }
        },
        help);
}

/// A choice from an enum's name table bound to `target`; --help shows its default.
template <class Enum, std::size_t N>
CLI::Option* add_choice(CLI::App& app, Options& o, const std::string& name, Enum& target,
                        const NameTable<Enum, N>& table, const std::string& help) {
    return add_parsed(
               app, o, name, target,
               [&table](const std::string& text) { return table.parse(text); },
               "must be one of " + table.choices(), help)
        ->default_str(std::string(table.name(target)));
}

void add_common(CLI::App& app, Options& o) {
    PackRequest& q = o.request;
    app.add_option("--count", o.count, "number of particles N (1 to 10000000)")->required();
    add_parsed(
        app, o, "--arrangement", q.arrangement,
        [](const std::string& text) { return parse_arrangement(text); },
        "must be one of " + std::string(arrangement_names()),
        "starting arrangement: single-column, small-dense, large-dense, loose-random")
        ->required();
    app.add_option("--seed", q.seed,
                   "random seed (colours, loose-random positions, random choices)")
        ->capture_default_str()
        ->check([](const std::string& text) { return sgmp::seed_rule(text); });
    app.add_option("--out", o.out, "output pack file (extended XYZ; .gz compresses)")->required();
    app.add_flag("--force", o.force, "overwrite an existing output file");
    app.add_option("--phi-target", q.phi_target,
                   "target packing fraction phi* in (0, 0.74048] for equal spheres, (0, 1) "
                   "for a blend of several sizes; sets the diameter by (N/3)(pi/6)d^3 = phi*")
        ->capture_default_str();
    o.size_modes_option =
        add_parsed(
            app, o, "--size-modes", q.size_modes,
            [](const std::string& text) { return parse_size_modes(text); },
            "must be positive diameter:fraction[:density] items, e.g. 1:0.7,0.5:0.3",
            "particle sizes as relative-diameter:fraction[:density] items, e.g. "
            "1:0.7,0.5:0.3 (species 1, 2, ... in this order; fractions in --fraction-basis); "
            "the scale s solves (N/3)(pi/6) sum n_i (a_i s)^3 = phi* with number fractions n_i")
            ->default_str(size_modes_to_string(q.size_modes));
    app.add_option("--size-distribution", o.size_distribution,
                   "size distribution as a CSV file: header diameter,fraction[,density], one "
                   "row per species (diameters in any unit; species 1, 2, ... in file order); "
                   "or lognormal:MEDIAN:SIGMA[:CLASSES[:QLO:QHI]]: ln D normal with that "
                   "median and sd, cut at the quantiles QLO, QHI (default 0.01, 0.99) into "
                   "CLASSES (default 10) species of equal fraction, each of its class's median "
                   "diameter");
    add_choice(app, o, "--fraction-basis", q.fraction_basis, fraction_bases(),
               "what the fractions of --size-modes or --size-distribution are: number, volume "
               "or mass (mass needs densities)");
}

void add_protocol(CLI::App& app, Options& o) {
    ProtocolParams& p = o.request.protocol;
    app.add_option("--circle-factor", p.circle_factor,
                   "circle factor F > 1: sweep radius = d/F (length units of the control volume)")
        ->capture_default_str();
    app.add_option("--sweep-positions", o.sweep_positions,
                   "positions tested on the sweep circle (>= 3; 120 = every 3 degrees)")
        ->capture_default_str();
    add_parsed(
        app, o, "--sweep-stages", o.sweep_stages,
        [](const std::string& text) { return parse_stages(text); },
        "must be comma-separated whole numbers, e.g. 8,120,720",
        "multi-stage sweep, increasing counts such as 8,120,720: a stage is tried "
        "only when the previous one found no free position (overrides "
        "--sweep-positions)")
        ->check([](const std::string& text) {
            return text.empty() ? "must list at least one count, e.g. 8,120,720" : "";
        });
    app.add_option("--lower-neighbours", p.lower_neighbours,
                   "size of the lower columnar neighbour list (>= 1; recorded, does not change "
                   "results: the fall scans the whole column below)")
        ->capture_default_str();
    add_choice(app, o, "--gap", p.gap, gap_rules(), "free arc to move toward: largest | random");
    add_choice(app, o, "--fall", p.fall, fall_modes(),
               "fall mode: exact (jump to the first contact; ends touching) | step (thesis "
               "steps of --fall-step; ends less than one step above the contact)");
    app.add_option("--fall-step", p.fall_step,
                   "downward increment of the step fall, 0 < step < d (control-volume units)")
        ->capture_default_str();
    add_choice(app, o, "--contact", p.contact, contact_models(),
               "contact model for resting particles: none | settle (drop onto the support "
               "and roll down over it to a second contact) | roll (roll on down to a stable "
               "rest on three spheres, or the floor or a wall)");
    app.add_option("--momentum", p.momentum,
                   "momentum weight m in [0, 1): move toward (1-m)*bisector + m*previous move")
        ->capture_default_str();
    add_choice(app, o, "--walls", p.walls, wall_rules(),
               "side walls: fix (a particle a move brings to a wall stops there, thesis) | "
               "block (walls are obstacles like particles)");
    app.add_option("--stall-moves", p.stall_moves,
                   "a particle making this many consecutive moves without falling rests (>= 1)")
        ->capture_default_str();
    app.add_option("--max-moves", p.max_moves,
                   "bound on sweep-and-move cycles per particle (>= 1); a particle reaching it "
                   "rests where its last fall left it")
        ->capture_default_str();
}

void add_relax(CLI::App& app, Options& o) {
    RelaxParams& r = o.request.relax;
    add_choice(app, o, "--relax", r.mode, relax_modes(),
               "after deposition: none | frictionless (relax the whole pack under gravity "
               "to an equilibrium of frictionless soft spheres by FIRE energy "
               "minimisation, then settle it as hard spheres into a certified equilibrium "
               "by linear programming; slow: about 15 s at N = 1002) | frictional (the "
               "FIRE stages with Coulomb friction: tangential springs capped at mu*F_n; "
               "not yet certified)");
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
                   "ones, so soft contacts end as gaps of at most s*(ri+rj); 0: contacts end "
                   "touching")
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
    app.add_option("--relax-settle-limit", r.settle_limit,
                   "bound on the LP iterations of the hard-sphere settling that ends the "
                   "relaxation (1 to 1000000); a pack that reaches it is usually not a certified "
                   "equilibrium")
        ->capture_default_str();
    app.add_option("--relax-friction", r.friction,
                   "sliding friction mu of --relax frictional (pairs and walls), in [0, 10]; "
                   "the DEM frictional class's own mu, untuned")
        ->capture_default_str();
    app.add_option("--relax-tangential-ratio", r.tangential_ratio,
                   "tangential over normal contact stiffness of --relax frictional, in (0, 1]")
        ->capture_default_str();
    app.add_flag("--keep-uncertified", o.keep_uncertified,
                 "write a relaxed pack that is not a certified equilibrium (its header says "
                 "certified=false); without it such a pack is refused: exit 1, no file");
}

/// The request of the command line: the count's range and the sweep stages checked
/// here, every other rule by the engine's `validate`.
/// The modes of --size-distribution FILE (size_modes.hpp); a bad file is a usage error
/// naming file:line.
void read_size_distribution(const Options& o, PackRequest& request) {
    const std::string& path = o.size_distribution;
    if (o.size_modes_option != nullptr && o.size_modes_option->count() > 0) {
        throw UsageError("--size-distribution " + path +
                         ": give either --size-modes or --size-distribution, not both");
    }
    if (is_lognormal(path)) {  // a continuous distribution, not a file
        request.size_modes = lognormal_modes(path);
        request.size_distribution = path;
        return;
    }
    std::ifstream in(path, std::ios::binary);
    if (!std::filesystem::is_regular_file(path) || !in) {
        throw UsageError("--size-distribution " + path + ": must name a readable file");
    }
    std::ostringstream text;
    text << in.rdbuf();
    try {
        request.size_modes = parse_size_distribution_csv(text.str(), path);
    } catch (const InputError& e) {
        throw UsageError(std::string("--size-distribution ") + e.what());
    }
    request.size_distribution = path;
}

/// Fractions of a valid distribution file that do not sum to 1 are normalised (the engine
/// does); the user is told, in one line.
void warn_unnormalised(const PackRequest& request) {
    double total = 0.0;
    for (const SizeMode& m : request.size_modes) {
        total += m.fraction;
    }
    if (!request.size_distribution.empty() && std::abs(total - 1.0) > 1e-9) {
        std::fprintf(stderr,
                     "sgmp: warning: --size-distribution %s: fractions sum to %s; normalised "
                     "to 1\n",
                     request.size_distribution.c_str(), format_number(total).c_str());
    }
}

PackRequest to_request(const Options& o) {
    if (o.count < 1 || o.count > static_cast<long long>(kMaxCount)) {
        throw ParameterError("count", std::to_string(o.count),
                             "must be between 1 and " + std::to_string(kMaxCount));
    }
    if (o.refused) {
        throw UsageError(*o.refused);
    }
    PackRequest request = o.request;
    if (!o.size_distribution.empty()) {
        read_size_distribution(o, request);
    }
    request.count = static_cast<std::size_t>(o.count);
    request.protocol.sweep_stages = o.sweep_stages.value_or(std::vector<int>{o.sweep_positions});
    validate(request);
    warn_unnormalised(request);
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

/// Why a relaxed pack is not certified, in one line.
std::string uncertified_reason(const Pack& pack) {
    const auto& m = pack.metadata;
    return "the relaxed pack is not a certified " + m.get("certificate").value_or("") +
           " equilibrium: sphere " + m.get("certificate_worst_id").value_or("?") +
           " is out of balance by " + m.get("certificate_residual_max").value_or("?") +
           " m*g (at most " + m.get("certificate_residual_tolerance").value_or("?") +
           "), deepest overlap " + m.get("certificate_overlap_max").value_or("?") + " d";
}

int run_pack(const Options& o) {
    const PackRequest request = to_request(o);
    check_out(o);
    // Progress once a run passes one second.
    cli::ProgressLine progress(false, std::chrono::seconds(5), std::chrono::seconds(1));
    const auto seconds_text = [&] {
        return " (" + std::to_string(static_cast<long>(progress.seconds())) + " s)";
    };
    const auto dropped = [&](std::size_t done, std::size_t total) {
        progress.update("sgmp: " + std::to_string(done) + " / " + std::to_string(total) +
                        " particles dropped" + seconds_text());
    };
    const auto relaxing = [&](const RelaxProgress& r) {
        using Phase = RelaxProgress::Phase;
        const std::string text =
            r.phase == Phase::Soft
                ? "relaxing: soft stage " + std::to_string(r.stage + 1) + " of " +
                      std::to_string(r.stages) + ", " + std::to_string(r.steps) + " steps"
            : r.phase == Phase::Clearing
                ? "relaxing: clearing the overlaps after " + std::to_string(r.steps) + " steps"
                : "settling as hard spheres: LP iteration " + std::to_string(r.settle_iteration) +
                      ", trust region " + format_number(r.settle_trust) + " d";
        progress.update("sgmp: " + text + seconds_text(), 1 + static_cast<int>(r.phase));
    };
    const Pack pack = make_pack(request, dropped, nullptr, relaxing);
    const double seconds = progress.seconds();
    progress.finish();
    if (pack.metadata.get("certified") == std::optional<std::string>("false") &&
        !o.keep_uncertified) {
        throw std::runtime_error(uncertified_reason(pack) +
                                 "; --keep-uncertified writes it with certified=false");
    }
    write_pack_file(o.out, pack, o.force);
    const double d = *pack.metadata.get_number("diameter");
    const OverlapCount overlaps = count_overlaps(pack.particles, Container{}, 1e-9 * d);
    std::printf(
        "sgmp: packed %zu particles, %s, d=%.6g, %.3f s, phi(control volume)=%.4f, "
        "overlaps=%zu -> %s\n",
        pack.particles.size(), std::string(to_string(request.arrangement)).c_str(), d, seconds,
        packing_fraction(pack, control_volume()), overlaps.pairs, o.out.c_str());
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
