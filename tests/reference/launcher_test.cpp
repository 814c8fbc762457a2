// Launching LIGGGHTS on K ranks: the words each launcher gets, Open MPI's root flag only
// where it belongs, and the processor grid from the container's shape.
#include <unistd.h>
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "sgmp/reference/launcher.hpp"
#include "sgmp/reference/pour_params.hpp"

namespace fs = std::filesystem;
using namespace sgmp::reference;

namespace {

/// Every program is "found" at /opt/bin/NAME (or NAME itself when it holds a '/').
LaunchEnvironment pretend(bool root) {
    return {root, [](const std::string& name) -> std::optional<fs::path> {
                if (name == "missing") {
                    return std::nullopt;
                }
                return name.find('/') != std::string::npos ? fs::path(name)
                                                           : fs::path("/opt/bin") / name;
            }};
}

using Words = std::vector<std::string>;

}  // namespace

BOOST_AUTO_TEST_CASE(each_launcher_gets_its_own_words) {
    BOOST_TEST(launch_words("srun", 4, pretend(true)) == (Words{"/opt/bin/srun", "-n", "4"}));
    // A plain `mpirun` that is not Open MPI's (MPICH, Intel MPI): never the root flag.
    BOOST_TEST(launch_words("mpirun", 3, pretend(true)) == (Words{"/opt/bin/mpirun", "-np", "3"}));
    BOOST_TEST(launch_words("mpiexec -n {np} -bind-to core", 8, pretend(false)) ==
               (Words{"/opt/bin/mpiexec", "-n", "8", "-bind-to", "core"}));
    BOOST_TEST(launch_words("charmrun +p{np}", 2, pretend(false)) ==
               (Words{"/opt/bin/charmrun", "+p2"}));
    BOOST_CHECK_THROW(launch_words("mpiexec -n 4", 4, pretend(false)), std::invalid_argument);
    BOOST_CHECK_THROW(launch_words("  ", 4, pretend(false)), std::invalid_argument);
    try {
        launch_words("missing", 2, pretend(false));
        BOOST_FAIL("a missing launcher must throw");
    } catch (const std::invalid_argument& e) {
        BOOST_TEST(std::string(e.what()) == "'missing' not found on PATH (needed for --ranks 2)");
    }
}

BOOST_AUTO_TEST_CASE(open_mpi_gets_allow_run_as_root_only_as_root) {
    // Debian's layout: mpirun -> mpirun.openmpi (through /etc/alternatives).
    const fs::path dir =
        fs::temp_directory_path() / ("sgmp-launcher-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    { std::ofstream(dir / "mpirun.openmpi") << "#!/bin/sh\n"; }
    fs::create_symlink(dir / "mpirun.openmpi", dir / "mpirun");
    { std::ofstream(dir / "mpirun.mpich") << "#!/bin/sh\n"; }
    const std::string open_mpi = (dir / "mpirun").string();
    BOOST_TEST(is_open_mpi(open_mpi));
    BOOST_TEST(!is_open_mpi(dir / "mpirun.mpich"));
    BOOST_TEST(launch_words(open_mpi, 2, pretend(true)) ==
               (Words{open_mpi, "-np", "2", "--allow-run-as-root"}));
    BOOST_TEST(launch_words(open_mpi, 2, pretend(false)) == (Words{open_mpi, "-np", "2"}));
    BOOST_TEST(launch_words((dir / "mpirun.mpich").string(), 2, pretend(true)).size() == 3u);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(grids_follow_the_container_and_the_option) {
    using Grid = std::array<int, 3>;
    BOOST_TEST((choose_processor_grid(1, 1.25, 1.25) == Grid{1, 1, 1}));
    BOOST_TEST((choose_processor_grid(2, 1.25, 1.25) == Grid{2, 1, 1}));
    BOOST_TEST((choose_processor_grid(4, 1.25, 1.25) == Grid{2, 1, 2}));
    BOOST_TEST((choose_processor_grid(6, 1.25, 1.25) == Grid{3, 1, 2}));
    BOOST_TEST((choose_processor_grid(7, 1.25, 1.25) == Grid{7, 1, 1}));  // prime
    BOOST_TEST((choose_processor_grid(16, 1.25, 1.25) == Grid{4, 1, 4}));
    // A long thin section (x four times z) is cut across x only.
    BOOST_TEST((choose_processor_grid(4, 5.0, 1.25) == Grid{4, 1, 1}));
    // Brute force: no divisor pair cuts less than the chosen one.
    for (int k = 1; k <= 64; ++k) {
        const Grid g = choose_processor_grid(k, 1.25, 2.0);
        BOOST_TEST(g[0] * g[1] * g[2] == k);
        for (int pz = 1; pz <= k; ++pz) {
            if (k % pz == 0) {
                BOOST_TEST((g[0] - 1) * 2.0 + (g[2] - 1) * 1.25 <=
                           (k / pz - 1) * 2.0 + (pz - 1) * 1.25 + 1e-12);
            }
        }
    }
    BOOST_TEST((parse_processor_grid("2,1,3") == Grid{2, 1, 3}));
    BOOST_TEST((parse_processor_grid("2 1 3") == Grid{2, 1, 3}));
    for (const char* bad : {"", "2,1", "2,1,0", "2,1,3,4", "a,1,1", "-1,1,1"}) {
        BOOST_TEST(!parse_processor_grid(bad), bad);
    }
    PourParams p;
    p.count = 150;
    p.ranks = 4;
    p.processors = "2,2,2";
    BOOST_CHECK_THROW(p.validate(), std::invalid_argument);
    p.processors = "1,1,4";
    BOOST_CHECK_NO_THROW(p.validate());
}
