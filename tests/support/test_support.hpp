#pragma once
// Helpers shared by the test suites: scratch directories under the build tree, reading
// files back, running a command as a user would, and the message of an InputError.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::testing {

/// A fresh directory under the build tree, removed at the end of the test.
class TestDirectory {
  public:
    explicit TestDirectory(const std::string& name)
        : path_(std::filesystem::path(SGMP_BINARY_DIR) / "test-scratch" / name) {
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TestDirectory() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TestDirectory(const TestDirectory&) = delete;
    TestDirectory& operator=(const TestDirectory&) = delete;
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

inline std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream content;
    content << in.rdbuf();
    return content.str();
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

/// What a command printed and how it ended.
struct CommandRun {
    int status = -1;  ///< its exit status; -1 when it did not exit (a signal)
    std::string out;  ///< what it wrote on stdout
    std::string err;  ///< what it wrote on stderr
};

/// Runs the shell command line `command` (sh -c, so `cd DIR && …` and `VAR=x …` work) with
/// stdout and stderr captured in the files `stdout` and `stderr` of `directory`.
inline CommandRun run_command(const std::string& command, const std::filesystem::path& directory) {
    const std::filesystem::path out = directory / "stdout";
    const std::filesystem::path err = directory / "stderr";
    const std::string line =
        "{ " + command + "\n} >'" + out.string() + "' 2>'" + err.string() + "'";
    const int raw = std::system(line.c_str());
    return CommandRun{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_bytes(out), read_bytes(err)};
}

/// A fresh scratch directory (TestDirectory) for running one program as a user would.
class ProgramScratch {
  public:
    ProgramScratch(const std::string& name, std::string program)
        : directory_(name), program_(std::move(program)) {}

    /// The path of `name` in the scratch directory, as text for command lines.
    [[nodiscard]] std::string path(const std::string& name) const { return (dir / name).string(); }
    /// Runs `PREFIX 'PROGRAM' ARGS` (the prefix e.g. `VAR=value` or `cd DIR &&`), its
    /// output captured in the files stdout and stderr of the scratch directory.
    [[nodiscard]] CommandRun run(const std::string& args, const std::string& prefix = "") const {
        return run_command(prefix + " '" + program_ + "' " + args, dir);
    }

  private:
    TestDirectory directory_;
    std::string program_;

  public:
    const std::filesystem::path& dir = directory_.path();  ///< the scratch directory
};

/// A sphere of radius r centred at (x, y, z), colour bin 0.
inline Particle sphere(std::int64_t id, double x, double y, double z, double r) {
    return Particle{id, Vec3(x, y, z), r, 0};
}

/// The message of the InputError that `read` throws; empty if it throws none.
template <class Read>
std::string input_error_of(Read&& read) {
    try {
        read();
    } catch (const InputError& error) {
        return error.what();
    }
    return {};
}

}  // namespace sgmp::testing
