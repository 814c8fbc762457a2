#include "launcher_options.hpp"

namespace sgmp::reference {

void add_launcher_options(CLI::App& command, PourRequest& request) {
    command
        .add_option("--launcher", request.launcher,
                    "how --ranks K > 1 start: mpirun (-np K; --allow-run-as-root only for Open "
                    "MPI as root), srun (-n K), or a command line with {np}, e.g. 'mpiexec -n "
                    "{np}'")
        ->capture_default_str();
}

}  // namespace sgmp::reference
