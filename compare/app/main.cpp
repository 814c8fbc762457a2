// sgmp-compare: metrics of sphere packs and agreement reports between groups of packs.
#include <CLI/CLI.hpp>
#include <string>

#include "command_support.hpp"
#include "sgmp/cli/run_main.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "sgmp/pack/version.hpp"

int main(int argc, char** argv) {
    using namespace sgmp::compare::cli;
    CLI::App app{
        "sgmp-compare " + std::string(sgmp::version()) +
        ": metrics of sphere packs (packing fraction, overlaps, coordination, g(r), Q6) and "
        "agreement reports between groups of packs. Lengths are in the pack's units (the "
        "control volume's side); *_over_d values and g(r) distances are in mean diameters d."};
    app.set_version_flag("--version", std::string(sgmp::version()));
    app.require_subcommand(1);
    const CommandRunner commands[] = {register_measure(app), register_report(app),
                                      register_crossval(app), register_regress(app),
                                      register_header(app)};
    const std::string command = command_line(argc, argv);
    return sgmp::cli::run_main(
        "sgmp-compare", app, [&] { app.parse(argc, argv); },
        [&] {
            sgmp::install_interrupt_handler("sgmp-compare");
            for (const CommandRunner& run : commands) {
                if (const int status = run(command); status >= 0) {
                    return status;
                }
            }
            return 2;  // unreachable: CLI11 requires one subcommand
        });
}
