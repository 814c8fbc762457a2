#include "sgmp/reference/launcher.hpp"

#include "sgmp/pack/parameter_error.hpp"

#include <unistd.h>

#include <charconv>
#include <sstream>
#include <stdexcept>

#include "sgmp/pack/executables.hpp"

namespace sgmp::reference {
namespace fs = std::filesystem;

LaunchEnvironment current_launch_environment() {
    return {::geteuid() == 0, [](const std::string& name) { return find_executable(name); }};
}

bool is_open_mpi(const fs::path& program) {
    std::error_code error;
    const fs::path resolved = fs::canonical(program, error);
    const std::string name = (error ? program : resolved).filename().string();
    return name.find("openmpi") != std::string::npos || name == "orterun" || name == "prterun";
}

std::vector<std::string> launch_words(const std::string& launcher, int ranks,
                                      const LaunchEnvironment& environment) {
    std::vector<std::string> words;
    std::istringstream split(launcher);
    for (std::string word; split >> word;) {
        words.push_back(word);
    }
    if (words.empty()) {
        throw ParameterError("launcher", "''",
                             "must be mpirun, srun or a command line "
                             "holding {np}");
    }
    const std::string np = std::to_string(ranks);
    const std::string base = fs::path(words.front()).filename().string();
    const auto program = environment.find(words.front());
    if (!program) {
        throw std::invalid_argument("'" + words.front() +
                                    "' not found on PATH (needed for --ranks " + np + ")");
    }
    if (words.size() == 1 && base == "srun") {
        return {program->string(), "-n", np};
    }
    if (words.size() == 1 && words.front().find("{np}") == std::string::npos) {
        // mpirun, mpiexec, orterun, mpirun.mpich …: every MPI launcher takes -np.
        words = {program->string(), "-np", np};
        if (environment.root && is_open_mpi(*program)) {
            words.push_back("--allow-run-as-root");
        }
        return words;
    }
    bool placed = false;
    for (std::string& word : words) {
        for (std::size_t at = word.find("{np}"); at != std::string::npos; at = word.find("{np}")) {
            word.replace(at, 4, np);
            placed = true;
        }
    }
    if (!placed) {
        throw ParameterError("launcher", "'" + launcher + "'",
                             "a command line must hold {np} where the rank count goes, e.g. "
                             "'mpiexec -n {np}'");
    }
    words.front() = program->string();
    return words;
}

std::array<int, 3> choose_processor_grid(int ranks, double x_width, double z_depth) {
    std::array<int, 3> best{ranks, 1, 1};
    double best_cut = (ranks - 1) * z_depth;
    for (int pz = 2; pz <= ranks; ++pz) {
        if (ranks % pz != 0) {
            continue;
        }
        const int px = ranks / pz;
        const double cut = (px - 1) * z_depth + (pz - 1) * x_width;
        if (cut < best_cut - 1e-12 * (x_width + z_depth)) {
            best = {px, 1, pz};
            best_cut = cut;
        }
    }
    return best;
}

std::optional<std::array<int, 3>> parse_processor_grid(const std::string& text) {
    std::array<int, 3> grid{};
    std::size_t start = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t end = i < 2 ? text.find_first_of(", ", start) : text.size();
        if (end == std::string::npos) {
            return std::nullopt;
        }
        const auto result = std::from_chars(text.data() + start, text.data() + end, grid[i]);
        if (end == start || result.ec != std::errc() || result.ptr != text.data() + end ||
            grid[i] < 1) {
            return std::nullopt;
        }
        start = end + 1;
    }
    return grid;
}

}  // namespace sgmp::reference
