#pragma once
// sgmp render: a picture of a pack rendered with POV-Ray (render_command.cpp).

#include <CLI/CLI.hpp>
#include <functional>

namespace sgmp::app {

struct RenderCommand {
    CLI::App* command = nullptr;
    /// Runs the command when it was chosen (errors as exceptions, for cli::run_main).
    std::function<int()> run;
};

/// Adds the `render` subcommand to `app`.
RenderCommand register_render(CLI::App& app);

}  // namespace sgmp::app
