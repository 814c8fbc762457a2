#pragma once
/// @file child_process.hpp
/// Runs a program in its own process group, handing each line of its merged standard
/// output and error to a callback as it arrives, and ends it (the whole group: SIGTERM,
/// then SIGKILL) on a timeout or when asked to stop.

#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sgmp {

struct ChildOptions {
    std::vector<std::string> argv;                         ///< argv[0] is looked up on PATH
    std::filesystem::path working_directory;               ///< empty: the current one
    std::optional<std::chrono::duration<double>> timeout;  ///< wall-clock limit
    /// Polled about ten times a second and after every line; true ends the child.
    std::function<bool()> should_stop;
};

enum class ChildEnd {
    exited,     ///< exited by itself; see exit_code
    signalled,  ///< killed by a signal it did not ask for; see signal
    timed_out,  ///< ended by us at the timeout
    stopped     ///< ended by us because should_stop returned true
};

struct ChildResult {
    ChildEnd end = ChildEnd::exited;
    int exit_code = 0;
    int signal = 0;
    double wall_seconds = 0.0;
};

/// Runs the child to its end. Throws std::runtime_error when it cannot be started.
ChildResult run_child(const ChildOptions& options,
                      const std::function<void(const std::string& line)>& on_line);

}  // namespace sgmp
