#include "settle_command.hpp"

#include "launcher_options.hpp"
#include "pour_command.hpp"
#include "pour_parameter_options.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <new>
#include <numbers>

#include "sgmp/cli/parameter_options.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/parameter_error.hpp"

namespace sgmp::reference {

namespace {

/// The start of a settle: the pack's centres and colours, its count and the φ* that gives
/// its diameter by the sizing rule. Throws std::invalid_argument naming the rule broken.
StartPositions start_from(const Pack& pack, const std::string& path, PourParams& p) {
    if (pack.particles.empty()) {
        throw std::invalid_argument(path + ": holds no spheres");
    }
    const double r = pack.particles.front().radius;
    StartPositions start;
    start.name = "pack";
    start.penetration_allowed_over_d = kMaxSettledPenetrationOverD;
    for (const Particle& particle : pack.particles) {
        if (std::abs(particle.radius - r) > 1e-9 * r) {
            throw std::invalid_argument(path +
                                        ": spheres of different radii; settle pours equal "
                                        "spheres only");
        }
        start.centers.push_back(particle.center);
        start.colors.push_back(particle.color);
    }
    p.count = pack.particles.size();
    p.arrangement = start.name;  // the input script then reads the positions (start.data)
    // (N/3)·(π/6)·d³ = φ*: the sizing rule read backwards gives back d = 2r.
    const double d = 2.0 * r;
    p.phi_target = static_cast<double>(p.count) / 3.0 * std::numbers::pi / 6.0 * d * d * d;
    if (const auto seed = pack.metadata.get_number("seed")) {
        p.seed = static_cast<std::uint64_t>(*seed);
    }
    return start;
}

}  // namespace

CLI::App* add_settle_command(CLI::App& app, SettleOptions& o) {
    CLI::App* cmd = app.add_subcommand(
        "settle",
        "Start LIGGGHTS from the spheres of a pack file (SGMP or DEM, equal spheres) at rest "
        "and run until settled, by the settling rule of pour; write the settled pack.");
    PourParams& p = o.request.parameters;
    cmd->add_option("pack", o.input, "Pack file to start from (extended XYZ or dump custom)")
        ->required()
        ->check(CLI::ExistingFile);
    // The pack gives the count, phi* and seed; the start is the pack itself.
    add_pour_parameter_options(
        *cmd, p, o.refused,
        {"friction", "tangential_damping", "restitution", "rolling_friction", "youngs_modulus",
         "poisson_ratio", "density", "gravity", "timestep_fraction", "settle_threshold",
         "check_time", "max_time", "ranks", "processors"},
        {"friction"});
    cmd->add_option("--out", o.out, "Output pack file (extended XYZ; .gz compresses)")->required();
    add_launcher_options(*cmd, o.request);
    cmd->add_option("--timeout", o.timeout, "Wall-clock limit in seconds; 0 means none")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--keep-work", o.keep_work, "Run in this directory and keep it");
    cmd->add_option("--liggghts", o.request.liggghts, "LIGGGHTS program (name on PATH or path)")
        ->capture_default_str();
    cmd->add_flag("--force", o.force, "Overwrite an existing output file");
    cmd->add_flag("--quiet", o.quiet, "No progress on stderr");
    return cmd;
}

int run_settle(SettleOptions& o, const PourObserver& observer,
               const std::function<bool()>& should_stop, const std::function<void()>& finish) {
    PourRequest& request = o.request;
    PourParams& p = request.parameters;
    cli::throw_refused(o.refused);
    Pack input;
    try {
        input = read_pack_file(o.input);
        request.start = start_from(input, o.input, p);
        p.validate();
        check_writable(o.out, o.force);
    } catch (const ParameterError&) {
        throw;  // run_main names the option
    } catch (const std::bad_alloc&) {
        throw;  // a runtime failure, not usage: run_main says "out of memory", status 1
    } catch (const std::exception& e) {
        std::cerr << "sgmp-reference: settle " << e.what() << '\n';
        return 2;
    }
    if (o.timeout > 0.0) {
        request.timeout = std::chrono::duration<double>(o.timeout);
    }
    request.work_directory = o.keep_work;
    request.should_stop = should_stop;
    try {
        PourResult result = pour(request, observer);
        finish();
        Metadata& m = result.pack.metadata;
        m.set("start", "pack");
        m.set("start_pack", std::filesystem::path(o.input).filename().string());
        m.set("start_generator", input.metadata.get("generator").value_or("unknown"));
        write_pack_file(o.out, result.pack, o.force);
        if (!o.quiet) {
            print_run_summary("settled", result, p.count, o.out);
        }
        return 0;
    } catch (const std::exception& e) {
        finish();
        return report_run_failure(e, should_stop && should_stop());
    }
}

}  // namespace sgmp::reference
