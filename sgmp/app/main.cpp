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
#include "sgmp/cli/parameter_options.hpp"
#include "sgmp/cli/progress_line.hpp"
#include "sgmp/cli/run_main.hpp"
#include "sgmp/cli/size_distribution_file.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/engine/pack_parameters.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/bounded_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/pack_overlaps.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/size_modes.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"
#include "sgmp/pack/version.hpp"

namespace {

using namespace sgmp;
using namespace sgmp::engine;

/// The command line's values. The pack parameters bind straight to the request through the
/// rows of the parameter table (pack_parameters.hpp; its defaults are the library's, shown by
/// --help); only the file options stay raw.
struct Options {
    std::string out;
    bool force = false;
    bool keep_uncertified = false;
    PackRequest request;
    /// --size-distribution FILE or lognormal:..., read into the request's modes by to_request.
    std::string size_distribution;
    CLI::Option* size_modes_option = nullptr;
    /// The first value refused while parsing; reported once parsing is done (so --help
    /// and missing options come first).
    std::optional<std::string> refused;
};

using cli::UsageError;

/// The option of one row of the pack parameter table (cli::add_parameter_option);
/// --size-distribution is kept as typed: a file is read by to_request.
CLI::Option* add_row(CLI::App& app, Options& o, const PackParameter& row) {
    if (row.name == "size_distribution") {
        return app.add_option(option_name(row.name), o.size_distribution, row.help);
    }
    return cli::add_parameter_option(app, row, o.request, o.refused);
}

/// Every row of the table's `group`, in table order.
void add_group(CLI::App& app, Options& o, std::string_view group) {
    for (const PackParameter& row : pack_parameters()) {
        if (row.group == group) {
            CLI::Option* added = add_row(app, o, row);
            if (row.name == "size_modes") {
                o.size_modes_option = added;
            }
        }
    }
}

void add_common(CLI::App& app, Options& o) {
    add_group(app, o, "count");
    add_group(app, o, "request");
    app.add_option("--out", o.out, "output pack file (extended XYZ; .gz compresses)")->required();
    app.add_flag("--force", o.force, "overwrite an existing output file");
}

void add_relax(CLI::App& app, Options& o) {
    add_group(app, o, "relax");
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
    if (is_lognormal(path)) {  // a continuous distribution, not a file: the row parses it
        set_pack_parameter(request, "size_distribution", path);
        return;
    }
    request.size_modes = cli::read_size_distribution_file(path, &request.largest_diameter);
    request.size_distribution = path;
}

PackRequest to_request(const Options& o) {
    cli::throw_refused(o.refused);
    PackRequest request = o.request;
    if (!o.size_distribution.empty()) {
        read_size_distribution(o, request);
    }
    validate(request);
    // Fractions not summing to 1 are normalised, and the user is told.
    if (!request.size_distribution.empty()) {
        cli::warn_unnormalised("sgmp", "--size-distribution " + request.size_distribution,
                               request.size_modes);
    } else if (o.size_modes_option != nullptr && o.size_modes_option->count() > 0) {
        cli::warn_unnormalised("sgmp", "--size-modes " + size_modes_to_string(request.size_modes),
                               request.size_modes);
    }
    return request;
}

/// `--config FILE` (config_file.hpp): its options are placed before the command line's.
std::vector<std::string> expand_config(std::vector<std::string> args, const CLI::App& app) {
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
        // Read whole and bounded: a file that cannot be read is refused (exit 1), never
        // taken for an empty one.
        std::istringstream in;
        try {
            in.str(read_bounded_file(path, kMaxSmallFileBytes, "a config file"));
        } catch (const InputError& e) {  // a bad file: exit 1
            throw std::runtime_error(std::string("--config ") + e.what());
        }
        try {
            // A key that names no option of the command is refused here, naming the file.
            const CLI::App* command = nullptr;
            try {
                command = app.get_subcommand(args.front());
            } catch (const CLI::OptionNotFound&) {
                // not a command: CLI11 says so when it parses
            }
            const auto known = [command](const std::string& option) {
                return command == nullptr || command->get_option_no_throw(option) != nullptr;
            };
            const auto typed = [&args](const std::string& option) {
                return std::any_of(args.begin(), args.end(), [&](const std::string& a) {
                    return a == option || a.rfind(option + "=", 0) == 0;
                });
            };
            const auto injected = sgmp::app::config_arguments(in, args.front(), known, typed);
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

/// Where a relaxation's time went, on stderr (the times are not recorded in the pack).
void print_relax_times(const Pack& pack, const PackStats& stats) {
    const RelaxStats& r = stats.relax;
    std::fprintf(stderr,
                 "sgmp: relaxation: soft stage %.3f s (%lld steps), settling %.3f s (%d "
                 "iterations, %lld sweeps, residual %.3g m*g), certificate %.3f s (forces: %s, "
                 "residual %s m*g, %s contacts, %s underconstrained)\n",
                 r.soft_seconds, r.steps, r.settle_seconds, r.settle_iterations, r.settle_sweeps,
                 r.settle_residual, stats.certificate_seconds,
                 pack.metadata.get("certificate_forces").value_or("-").c_str(),
                 pack.metadata.get("certificate_residual_max").value_or("-").c_str(),
                 pack.metadata.get("certificate_contacts").value_or("-").c_str(),
                 pack.metadata.get("certificate_underconstrained").value_or("-").c_str());
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
            : r.phase == Phase::Dynamics
                ? "settling as hard spheres: contact-dynamics step " +
                      std::to_string(r.settle_iteration) + ", residual " +
                      format_number(r.settle_trust) + " m*g"
                : "settling as hard spheres: LP iteration " + std::to_string(r.settle_iteration) +
                      ", trust region " + format_number(r.settle_trust) + " d";
        progress.update("sgmp: " + text + seconds_text(), 1 + static_cast<int>(r.phase));
    };
    PackStats stats;
    const Pack pack =
        cli::while_doing("building the pack of " + std::to_string(request.count) + " spheres",
                         [&] { return make_pack(request, dropped, &stats, relaxing); });
    const double seconds = progress.seconds();
    progress.finish();
    if (pack.metadata.get("certified") == std::optional<std::string>("false") &&
        !o.keep_uncertified) {
        throw std::runtime_error(uncertified_reason(pack) +
                                 "; --keep-uncertified writes it with certified=false");
    }
    if (request.relax.mode != RelaxMode::None) {  // after the refusal: that stays one line
        print_relax_times(pack, stats);
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
    add_group(*pack, pack_options, "protocol");
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
        args = expand_config(std::move(args), app);
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
