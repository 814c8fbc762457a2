#include "pour_command.hpp"

#include "launcher_options.hpp"
#include "pour_parameter_options.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "sgmp/cli/parameter_options.hpp"
#include "sgmp/cli/run_main.hpp"
#include "sgmp/cli/size_distribution_file.hpp"
#include "sgmp/engine/arrangement.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/size_modes.hpp"
#include "sgmp/reference/pour_parameters.hpp"

namespace sgmp::reference {
namespace {

/// The engine's starting arrangement for this pour (same count, φ*, hence diameter, and
/// seed), made by the engine itself.
StartPositions start_positions(const std::string& name, const PourParams& p) {
    engine::PackRequest request;
    request.count = p.count;
    request.arrangement = *engine::parse_arrangement(name);
    request.seed = p.seed;
    request.phi_target = p.phi_target;
    const Pack pack = engine::make_start_pack(request);
    StartPositions start;
    start.name = std::string(engine::to_string(request.arrangement));
    for (const Particle& particle : pack.particles) {
        start.centers.push_back(particle.center);
        start.colors.push_back(particle.color);
    }
    return start;
}

/// The modes of --size-distribution FILE or lognormal:… (size_modes.hpp), as sgmp pack
/// reads them; a bad file is a usage error naming file:line. Fractions that do not sum to
/// 1 are normalised, in one warning line.
void read_size_distribution(const PourOptions& o, PourParams& p) {
    const std::string& path = o.size_distribution;
    if (o.size_modes_option != nullptr && o.size_modes_option->count() > 0) {
        throw cli::UsageError("--size-distribution " + path +
                              ": give either --size-modes or --size-distribution, not both");
    }
    if (is_lognormal(path)) {
        const PourParameter* row = find_row(pour_parameters(), "size_distribution");
        if (!row->parse(p, path)) {
            throw ParameterError(row->name, path, row->rule);
        }
        return;
    }
    p.size_modes = cli::read_size_distribution_file(path);
    p.size_distribution = path;
    cli::warn_unnormalised("sgmp-reference", "--size-distribution " + path, p.size_modes);
}

}  // namespace

CLI::App* add_pour_command(CLI::App& app, PourOptions& o) {
    CLI::App* cmd = app.add_subcommand(
        "pour",
        "Pour N spheres (equal, or a blend as sgmp pack makes it) into the container and write "
        "the settled pack.");
    PourParams& p = o.request.parameters;
    add_pour_parameter_options(*cmd, p, o.refused, {}, {"count", "seed"});
    // A distribution may be a file, which the front end reads (run_pour).
    if (CLI::Option* table_option = cmd->get_option_no_throw("--size-distribution")) {
        const std::string help = table_option->get_description();
        cmd->remove_option(table_option);
        cmd->add_option("--size-distribution", o.size_distribution, help);
    }
    o.size_modes_option = cmd->get_option_no_throw("--size-modes");
    cmd->add_option("--out", o.out, "Output pack file (extended XYZ; .gz compresses)")->required();
    add_launcher_options(*cmd, o.request);
    cmd->add_option("--timeout", o.timeout, "Wall-clock limit in seconds; 0 means none")
        ->capture_default_str()
        ->check([](const std::string& text) {
            return sgmp::finite_range_rule(text, 0.0, 2592000.0, "[0, 2592000] s (30 days)");
        });
    cmd->add_option("--from-arrangement", o.arrangement,
                    std::string("Start from an SGMP starting arrangement (") +
                        std::string(sgmp::engine::arrangement_names()) +
                        ", made with --seed) instead of a loose random cloud")
        ->check([](const std::string& name) {
            return sgmp::engine::parse_arrangement(name)
                       ? std::string()
                       : "must be one of " + std::string(sgmp::engine::arrangement_names());
        });
    cmd->add_flag("--force", o.force, "Overwrite an existing output file");
    cmd->add_option("--keep-work", o.keep_work,
                    "Run in this directory and keep it (input script, log, dump); "
                    "default: a temporary directory, removed afterwards");
    cmd->add_option("--liggghts", o.request.liggghts, "LIGGGHTS program (name on PATH or path)")
        ->capture_default_str();
    cmd->add_flag("--quiet", o.quiet, "No progress on stderr");
    return cmd;
}

int run_pour(PourOptions& o, const PourObserver& observer, const std::function<bool()>& interrupted,
             const std::function<void()>& finish) {
    PourRequest& request = o.request;
    PourParams& p = request.parameters;
    cli::throw_refused(o.refused);
    if (!o.size_distribution.empty()) {
        read_size_distribution(o, p);
    }
    p.validate();
    try {
        check_writable(o.out, o.force);
    } catch (const std::exception& e) {
        throw cli::UsageError(std::string("--out ") + e.what());
    }
    if (o.timeout > 0.0) {
        request.timeout = std::chrono::duration<double>(o.timeout);
    }
    request.work_directory = o.keep_work;
    if (!o.arrangement.empty()) {
        request.start = start_positions(o.arrangement, p);
        p.arrangement = o.arrangement;
    }
    request.should_stop = interrupted;
    try {
        const auto result = pour(request, observer);
        finish();
        if (interrupted()) {
            std::cerr << "sgmp-reference: interrupted after the pour: no pack written\n";
            return kInterruptedStatus;
        }
        write_pack_file(o.out, result.pack, o.force);
        if (!o.quiet) {
            print_run_summary("poured", result, p.count, o.out);
        }
        return 0;
    } catch (const std::exception& e) {
        finish();
        return report_run_failure(e, interrupted());
    }
}

void print_run_summary(const char* verb, const PourResult& result, std::size_t count,
                       const std::string& out) {
    char summary[256];
    std::snprintf(summary, sizeof summary,
                  "%s %zu spheres in %.1f s, %lld steps; settling measure %.3g; max overlap %.3g "
                  "d; phi(control volume) %.4f; wrote ",
                  verb, count, result.wall_seconds, static_cast<long long>(result.steps),
                  result.ke_ratio, result.max_overlap_over_d, result.phi_control_volume);
    std::cerr << summary << printable(out) << '\n';
}

int report_run_failure(const std::exception& error, bool interrupted) {
    if (const auto* bad = dynamic_cast<const ParameterError*>(&error); bad != nullptr) {
        // A parameter found bad only when the run starts (the launcher): a usage error.
        std::cerr << "sgmp-reference: " << printable(cli::usage_message(*bad)) << '\n';
        return 2;
    }
    std::cerr << "sgmp-reference: " << printable(cli::failure_message(error)) << '\n';
    if (const auto* pour_error = dynamic_cast<const PourError*>(&error);
        pour_error != nullptr && !pour_error->log_tail().empty()) {
        std::cerr << "--- last lines of its output ---\n";
        for (const auto& line : pour_error->log_tail()) {
            std::cerr << "  " << printable(line) << '\n';
        }
    }
    return interrupted ? kInterruptedStatus : 1;
}

}  // namespace sgmp::reference
