// sgmp-reference: DEM reference packs poured with LIGGGHTS.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

#include "launcher_options.hpp"
#include "settle_command.hpp"
#include "sgmp/engine/arrangement.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/version.hpp"
#include "sgmp/reference/pour.hpp"

namespace {

using sgmp::reference::PourPhase;
using sgmp::reference::PourProgress;

std::atomic<bool> g_interrupted = false;
/// While LIGGGHTS runs, an interrupt stops it through should_stop (the pour removes its
/// work directory and reports); at any other time it removes the temporaries and exits.
std::atomic<bool> g_pouring = false;

void install_signal_handlers() {
    sgmp::install_interrupt_handler("sgmp-reference", [] {
        g_interrupted = true;
        return g_pouring.load();
    });
}

/// Progress on stderr: rewritten in place on a terminal, one line every few seconds
/// otherwise (logs of background runs stay short).
class ProgressPrinter {
  public:
    explicit ProgressPrinter(bool quiet) : quiet_(quiet), tty_(isatty(STDERR_FILENO) != 0) {}

    void operator()(const PourProgress& p) {
        if (quiet_) {
            return;
        }
        std::string text;
        if (p.phase == PourPhase::falling) {
            const double percent =
                p.phase_steps > 0 ? 100.0 * static_cast<double>(p.step) / p.phase_steps : 0.0;
            text = "fall: step " + std::to_string(p.step) + " of " + std::to_string(p.phase_steps) +
                   " (" + std::to_string(static_cast<int>(percent)) + " %)";
        } else if (p.phase == PourPhase::settling) {
            char buffer[160];
            std::snprintf(buffer, sizeof buffer,
                          "settling: step %lld, KE/(m g d) = %.3g -> below %.3g (cap %lld)",
                          static_cast<long long>(p.step), p.ke_ratio, p.threshold,
                          static_cast<long long>(p.phase_steps));
            text = buffer;
        } else {
            return;
        }
        const auto now = std::chrono::steady_clock::now();
        if (tty_) {
            std::cerr << "\r\033[K" << text << std::flush;
            shown_ = true;
        } else if (p.phase != last_phase_ || now - last_ > std::chrono::seconds(5)) {
            std::cerr << text << '\n';
            last_ = now;
        }
        last_phase_ = p.phase;
    }
    void finish() {
        if (shown_) {
            std::cerr << '\n';
            shown_ = false;
        }
    }

  private:
    bool quiet_;
    bool tty_;
    bool shown_ = false;
    PourPhase last_phase_ = PourPhase::starting;
    std::chrono::steady_clock::time_point last_{};
};

/// The engine's starting arrangement for this pour (same count, diameter and seed).
sgmp::reference::StartPositions start_positions(const std::string& name,
                                                const sgmp::reference::PourParameters& p) {
    const auto kind = sgmp::engine::parse_arrangement(name);
    sgmp::Random random(p.seed);
    const auto particles = sgmp::engine::make_arrangement(*kind, p.count, p.diameter(), random);
    sgmp::reference::StartPositions start;
    start.name = std::string(sgmp::engine::to_string(*kind));
    for (const auto& particle : particles) {
        start.centers.push_back(particle.center);
        start.colours.push_back(particle.color);
    }
    return start;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "sgmp-reference: DEM reference packs for the SGMP testbed, poured under gravity "
        "with LIGGGHTS (units: SI, 1 project length unit = 1 m)."};
    app.set_version_flag("--version", std::string(sgmp::version()));
    app.require_subcommand(1);
    CLI::App* pour_cmd = app.add_subcommand(
        "pour", "Pour N equal spheres into the container and write the settled pack.");

    sgmp::reference::PourRequest request;
    auto& p = request.parameters;
    std::string out;
    std::string keep_work;
    std::string arrangement;
    double timeout = 0.0;
    bool force = false;
    bool quiet = false;
    pour_cmd
        ->add_option("--count", p.count,
                     "Number of spheres N; d follows the sizing rule "
                     "(N/3)(pi/6)d^3 = phi_target")
        ->required()
        ->check(CLI::Range(1, 1000000));
    pour_cmd
        ->add_option("--seed", p.seed,
                     "Seed of the LIGGGHTS insertion and the colour "
                     "labels (integer)")
        ->required()
        ->check([](const std::string& text) { return sgmp::seed_rule(text); });
    pour_cmd
        ->add_option("--friction", p.friction,
                     "Sliding friction coefficient mu, particles and walls")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 10.0));
    pour_cmd->add_option("--out", out, "Output pack file (extended XYZ; .gz compresses)")
        ->required();
    pour_cmd
        ->add_option("--ranks", p.ranks,
                     "MPI ranks; above 1 runs LIGGGHTS under --launcher with a processor "
                     "grid chosen from the container (PY = 1: x and z split, never the fall)")
        ->capture_default_str()
        ->check(CLI::Range(1, 64));
    pour_cmd->add_option("--timeout", timeout, "Wall-clock limit in seconds; 0 means none")
        ->capture_default_str()
        ->check([](const std::string& text) {
            return sgmp::finite_range_rule(text, 0.0, 2592000.0, "[0, 2592000] s (30 days)");
        });
    pour_cmd
        ->add_option("--from-arrangement", arrangement,
                     std::string("Start from an SGMP starting arrangement (") +
                         std::string(sgmp::engine::arrangement_names()) +
                         ", made with --seed) instead of a loose random cloud")
        ->check([](const std::string& name) {
            return sgmp::engine::parse_arrangement(name)
                       ? std::string()
                       : "must be one of " + std::string(sgmp::engine::arrangement_names());
        });
    pour_cmd
        ->add_option("--start-jitter", p.start_jitter,
                     "With --from-arrangement: move each sphere horizontally by a random "
                     "offset up to this fraction of d (no overlaps created), which breaks "
                     "symmetries DEM keeps for ever (a single column lands as a tower)")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 0.5));
    pour_cmd->add_flag("--force", force, "Overwrite an existing output file");
    pour_cmd->add_option("--keep-work", keep_work,
                         "Run in this directory and keep it (input script, log, dump); "
                         "default: a temporary directory, removed afterwards");
    pour_cmd->add_option("--restitution", p.restitution, "Normal coefficient of restitution e")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    pour_cmd
        ->add_option("--rolling-friction", p.rolling_friction,
                     "Rolling friction coefficient (constant directional torque)")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    std::string tangential_damping = "on";
    pour_cmd
        ->add_option("--tangential-damping", tangential_damping,
                     "Viscous damping of the tangential contact spring, on or off (off for "
                     "exactly frictionless pours: at mu = 0 it still turns the spheres)")
        ->capture_default_str()
        ->check(CLI::IsMember({"on", "off"}));
    pour_cmd
        ->add_option("--youngs-modulus", p.youngs_modulus,
                     "Young's modulus E in Pa (must exceed 5e6)")
        ->capture_default_str();
    pour_cmd->add_option("--poisson-ratio", p.poisson_ratio, "Poisson's ratio nu")
        ->capture_default_str();
    pour_cmd->add_option("--density", p.density, "Particle density in kg/m^3")
        ->capture_default_str();
    pour_cmd->add_option("--gravity", p.gravity, "Gravitational acceleration in m/s^2 (along -Y)")
        ->capture_default_str();
    pour_cmd
        ->add_option("--timestep-fraction", p.timestep_fraction,
                     "Time step as a fraction of the Rayleigh time")
        ->capture_default_str();
    pour_cmd
        ->add_option("--settle-threshold", p.settle_threshold,
                     "Settled when the translational kinetic energy per particle stays "
                     "below this times m g d at two consecutive checks")
        ->capture_default_str();
    pour_cmd->add_option("--check-time", p.check_time, "Simulated seconds between settling checks")
        ->capture_default_str();
    pour_cmd
        ->add_option("--max-time", p.max_time,
                     "Simulated seconds allowed before the pour counts as not settled "
                     "(the step cap)")
        ->capture_default_str();
    pour_cmd
        ->add_option("--cloud-fraction", p.cloud_fraction,
                     "Solid fraction of the starting cloud (sets its height)")
        ->capture_default_str();
    pour_cmd
        ->add_option("--phi-target", p.phi_target,
                     "Target packing fraction phi* of the sizing rule")
        ->capture_default_str();
    add_launcher_options(*pour_cmd, request);
    pour_cmd->add_option("--liggghts", request.liggghts, "LIGGGHTS program (name on PATH or path)")
        ->capture_default_str();
    pour_cmd->add_flag("--quiet", quiet, "No progress on stderr");
    sgmp::reference::SettleOptions settle;
    CLI::App* settle_cmd = sgmp::reference::add_settle_command(app, settle);

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);  // help and --version
    } catch (const CLI::ParseError& e) {
        std::cerr << "sgmp-reference: " << sgmp::printable(e.what()) << " (see --help)\n";
        return 2;
    }
    if (settle_cmd->parsed()) {
        install_signal_handlers();
        ProgressPrinter printer(settle.quiet);
        return sgmp::reference::run_settle(
            settle, [&printer](const PourProgress& progress) { printer(progress); },
            [] { return g_interrupted != 0; }, [&printer] { printer.finish(); });
    }

    p.tangential_damping = tangential_damping == "on";
    try {
        p.validate();
    } catch (const std::invalid_argument& e) {
        std::cerr << "sgmp-reference: " << sgmp::printable(e.what()) << '\n';
        return 2;
    }
    try {
        sgmp::check_writable(out, force);
    } catch (const std::exception& e) {
        std::cerr << "sgmp-reference: --out " << sgmp::printable(e.what()) << '\n';
        return 2;
    }
    if (timeout > 0.0) {
        request.timeout = std::chrono::duration<double>(timeout);
    }
    request.work_directory = keep_work;
    if (!arrangement.empty()) {
        request.start = start_positions(arrangement, p);
        p.arrangement = arrangement;
    }
    install_signal_handlers();
    request.should_stop = [] { return g_interrupted.load(); };

    ProgressPrinter printer(quiet);
    try {
        g_pouring = true;
        const auto result = sgmp::reference::pour(
            request, [&printer](const PourProgress& progress) { printer(progress); });
        g_pouring = false;
        printer.finish();
        if (g_interrupted) {
            std::cerr << "sgmp-reference: interrupted after the pour: no pack written\n";
            return sgmp::kInterruptedStatus;
        }
        sgmp::write_pack_file(out, result.pack, force);
        if (!quiet) {
            char summary[256];
            std::snprintf(summary, sizeof summary,
                          "poured %zu spheres in %.1f s, %lld steps; settling measure %.3g; max "
                          "overlap %.3g d; phi(control volume) %.4f; wrote ",
                          p.count, result.wall_seconds, static_cast<long long>(result.steps),
                          result.ke_ratio, result.max_overlap_over_d, result.phi_control_volume);
            std::cerr << summary << out << '\n';
        }
        return 0;
    } catch (const sgmp::reference::PourError& e) {
        printer.finish();
        std::cerr << "sgmp-reference: " << sgmp::printable(e.what()) << '\n';
        if (!e.log_tail().empty()) {
            std::cerr << "--- last lines of LIGGGHTS output ---\n";
            for (const auto& line : e.log_tail()) {
                std::cerr << "  " << sgmp::printable(line) << '\n';
            }
        }
        return g_interrupted ? sgmp::kInterruptedStatus : 1;
    } catch (const std::exception& e) {
        printer.finish();
        std::cerr << "sgmp-reference: " << sgmp::printable(e.what()) << '\n';
        return g_interrupted ? sgmp::kInterruptedStatus : 1;
    }
}
