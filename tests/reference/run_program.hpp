#pragma once
// Runs sgmp-reference as a user would, for the tests: arguments, an optional PATH, and
// optionally a signal sent once a file appears (the moment the fake LIGGGHTS started).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sgmp::reference::testing {

struct ProgramRun {
    int exit_code = -1;
    std::string stderr_text;
};

struct ProgramOptions {
    std::vector<std::string> args;    ///< after the executable
    std::optional<std::string> path;  ///< PATH for the program
    std::optional<std::filesystem::path> signal_when_exists;
    int signal = 0;
};

ProgramRun run_program(const std::string& executable, const ProgramOptions& options);

/// A fresh empty directory under the system's temporary directory.
std::filesystem::path fresh_directory(const std::string& stem);

/// Writes an executable shell script.
void write_script(const std::filesystem::path& path, const std::string& body);

}  // namespace sgmp::reference::testing
