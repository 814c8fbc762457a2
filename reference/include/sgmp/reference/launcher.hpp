#pragma once
/// @file launcher.hpp
/// Running LIGGGHTS on K MPI ranks under any launcher, and the processor grid of its
/// domain.
///
/// Launchers (`--launcher`):
/// - `mpirun` (or any one program: mpiexec, a path): `PROGRAM -np K`; `--allow-run-as-root`
///   is added only for Open MPI's launcher (told by the file the name resolves to: Debian's
///   mpirun → mpirun.openmpi, or orterun / prterun) and only when running as root — MPICH
///   and Intel MPI reject the flag, and Open MPI needs it only for root;
/// - `srun`: `srun -n K` (Slurm, inside an allocation);
/// - any other command line holding `{np}`, split at spaces with `{np}` replaced by K, e.g.
///   `mpiexec -n {np} -bind-to core`.
///
/// Processor grid PX PY PZ (LIGGGHTS `processors`, PX·PY·PZ = K): by default PY = 1 (never
/// split along the fall, where the spheres gather at the bottom) and PX·PZ = K minimising
/// the cut area (PX − 1)·Z + (PZ − 1)·X of the container's X × Z section (ties: the larger
/// PX); on the square thesis container K = 4 gives 2 1 2 and K = 6 gives 3 1 2.

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sgmp::reference {

/// How launch_words sees the machine (tests substitute both).
struct LaunchEnvironment {
    bool root = false;  // effective user id 0
    std::function<std::optional<std::filesystem::path>(const std::string&)> find;  // on PATH
};
/// This process's environment: geteuid() and find_executable.
LaunchEnvironment current_launch_environment();

/// True when `program` (resolved through symbolic links) is Open MPI's launcher.
bool is_open_mpi(const std::filesystem::path& program);

/// The words that start `ranks` ranks, to be followed by the program and its arguments.
/// Throws std::invalid_argument naming the launcher for an empty one, a command line
/// without {np}, or a program not found on PATH.
std::vector<std::string> launch_words(const std::string& launcher, int ranks,
                                      const LaunchEnvironment& environment);

/// The default grid for `ranks` ranks on a section of x width `x_width` and z depth
/// `z_depth` (see above).
std::array<int, 3> choose_processor_grid(int ranks, double x_width, double z_depth);

/// Parses "PX,PY,PZ" (or "PX PY PZ"); nullopt unless three whole numbers >= 1.
std::optional<std::array<int, 3>> parse_processor_grid(const std::string& text);

}  // namespace sgmp::reference
