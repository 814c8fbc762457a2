#pragma once
// `sgmp batch`: many packs in one process (seed lists × a parameter grid), one
// summary.csv; split across MPI ranks or `--shard I/N`; `--merge` joins shard summaries.

#include <CLI/CLI.hpp>
#include <memory>

namespace sgmp::app {

class BatchCommand {
  public:
    /// Adds the `batch` subcommand to `app`.
    explicit BatchCommand(CLI::App& app);
    ~BatchCommand();
    [[nodiscard]] bool parsed() const;
    /// Runs the parsed command; returns the exit status (errors are printed as one line).
    int run();

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace sgmp::app
