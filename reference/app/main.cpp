// sgmp-reference: DEM reference packs poured with LIGGGHTS.
#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdio>
#include <iostream>
#include <string>

#include "pour_command.hpp"
#include "settle_command.hpp"
#include "sgmp/cli/progress_line.hpp"
#include "sgmp/cli/run_main.hpp"
#include "sgmp/pack/interrupt.hpp"
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

/// A pour's progress on stderr (cli::ProgressLine: in place on a terminal, a line every
/// few seconds in a log).
class ProgressPrinter {
  public:
    explicit ProgressPrinter(bool quiet) : line_(quiet) {}

    void operator()(const PourProgress& p) {
        if (p.phase == PourPhase::falling) {
            const double percent =
                p.phase_steps > 0 ? 100.0 * static_cast<double>(p.step) / p.phase_steps : 0.0;
            line_.update("fall: step " + std::to_string(p.step) + " of " +
                             std::to_string(p.phase_steps) + " (" +
                             std::to_string(static_cast<int>(percent)) + " %)",
                         static_cast<int>(p.phase));
        } else if (p.phase == PourPhase::settling) {
            char buffer[160];
            std::snprintf(buffer, sizeof buffer,
                          "settling: step %lld, KE/(m g d) = %.3g -> below %.3g (cap %lld)",
                          static_cast<long long>(p.step), p.ke_ratio, p.threshold,
                          static_cast<long long>(p.phase_steps));
            line_.update(buffer, static_cast<int>(p.phase));
        }
    }
    void finish() { line_.finish(); }

  private:
    sgmp::cli::ProgressLine line_;
};

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "sgmp-reference: DEM reference packs for the SGMP testbed, poured under gravity "
        "with LIGGGHTS (units: SI, 1 project length unit = 1 m)."};
    app.set_version_flag("--version", std::string(sgmp::version()));
    app.require_subcommand(1);
    sgmp::reference::PourOptions pour;
    CLI::App* pour_cmd = sgmp::reference::add_pour_command(app, pour);
    sgmp::reference::SettleOptions settle;
    sgmp::reference::add_settle_command(app, settle);
    return sgmp::cli::run_main(
        "sgmp-reference", app, [&] { app.parse(argc, argv); },
        [&] {
            install_signal_handlers();
            ProgressPrinter printer(pour_cmd->parsed() ? pour.quiet : settle.quiet);
            const auto observer = [&printer](const PourProgress& progress) { printer(progress); };
            const auto interrupted = [] { return g_interrupted.load(); };
            const auto finish = [&printer] {
                g_pouring = false;  // LIGGGHTS has ended: an interrupt now exits at once
                printer.finish();
            };
            if (pour_cmd->parsed()) {
                g_pouring = true;
                return sgmp::reference::run_pour(pour, observer, interrupted, finish);
            }
            return sgmp::reference::run_settle(settle, observer, interrupted, finish);
        });
}
