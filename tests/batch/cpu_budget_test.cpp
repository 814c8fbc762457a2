// The thread budget: affinity mask, then OMP_NUM_THREADS, then SLURM_CPUS_PER_TASK, then
// hardware_concurrency; and the real process under taskset and those variables.
#include <sys/wait.h>
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <cstdio>
#include <string>

#include "sgmp/pack/cpu_budget.hpp"

using sgmp::cpu_budget;
using sgmp::CpuBudgetInputs;

BOOST_AUTO_TEST_CASE(budget_follows_mask_then_environment) {
    BOOST_TEST(cpu_budget({std::nullopt, std::nullopt, std::nullopt, 8}) == 8u);
    BOOST_TEST(cpu_budget({3u, std::nullopt, std::nullopt, 8}) == 3u);  // taskset -c 0-2
    BOOST_TEST(cpu_budget({8u, "2", std::nullopt, 8}) == 2u);
    BOOST_TEST(cpu_budget({8u, "4,2", std::nullopt, 8}) == 4u);  // nested list
    BOOST_TEST(cpu_budget({2u, "16", std::nullopt, 8}) == 2u);   // never above the mask
    BOOST_TEST(cpu_budget({8u, std::nullopt, "3", 8}) == 3u);    // Slurm allocation
    BOOST_TEST(cpu_budget({8u, "5", "3", 8}) == 5u);             // OMP_NUM_THREADS first
    BOOST_TEST(cpu_budget({8u, "x", "3", 8}) == 3u);             // invalid: ignored
    BOOST_TEST(cpu_budget({8u, "0", "-1", 8}) == 8u);
    BOOST_TEST(cpu_budget({std::nullopt, std::nullopt, std::nullopt, 0}) == 1u);  // unknown
}

namespace {

/// The thread count `sgmp batch` reports for one tiny pack, run under `prefix`.
unsigned batch_threads(const std::string& prefix) {
    const std::string summary = "/tmp/sgmp-budget-test-" + std::to_string(::getpid()) + ".csv";
    const std::string command = prefix + " '" + SGMP_EXECUTABLE +
                                "' batch --seeds 1 --count 2 --arrangement small-dense --no-packs "
                                "--summary " +
                                summary + " --force --progress-seconds 0 2>&1";
    FILE* pipe = ::popen(command.c_str(), "r");
    BOOST_REQUIRE(pipe != nullptr);
    char buffer[512] = {};
    std::string out;
    while (std::fgets(buffer, sizeof(buffer), pipe) != nullptr) {
        out += buffer;
    }
    ::pclose(pipe);
    std::remove(summary.c_str());
    const std::size_t x = out.find(" rank(s) x ");
    BOOST_REQUIRE_MESSAGE(x != std::string::npos, out);
    return static_cast<unsigned>(std::stoul(out.substr(x + 11)));
}

}  // namespace

BOOST_AUTO_TEST_CASE(tools_honour_taskset_and_the_environment) {
    const auto inputs = sgmp::current_cpu_budget_inputs();
    BOOST_REQUIRE(inputs.affinity);
    const std::string clean = "env -u OMP_NUM_THREADS -u SLURM_CPUS_PER_TASK";
    BOOST_TEST(batch_threads(clean + " taskset -c 0") == 1u);
    BOOST_TEST(batch_threads(clean + " OMP_NUM_THREADS=1") == 1u);
    BOOST_TEST(batch_threads(clean + " SLURM_CPUS_PER_TASK=1") == 1u);
    BOOST_TEST(batch_threads(clean) == *inputs.affinity);
    BOOST_TEST(batch_threads(clean + " OMP_NUM_THREADS=999") == *inputs.affinity);
}
