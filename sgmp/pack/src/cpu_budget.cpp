#include "sgmp/pack/cpu_budget.hpp"

#include <sched.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <thread>

namespace sgmp {
namespace {

/// A whole number ≥ 1 at the start of `text` up to an optional ',' (OpenMP's nested list).
std::optional<unsigned> positive_count(const std::optional<std::string>& text) {
    if (!text) {
        return std::nullopt;
    }
    const std::string first = text->substr(0, text->find(','));
    unsigned value = 0;
    const auto* end = first.data() + first.size();
    const auto result = std::from_chars(first.data(), end, value);
    if (first.empty() || result.ec != std::errc() || result.ptr != end || value == 0) {
        return std::nullopt;
    }
    return value;
}

std::optional<std::string> environment(const char* name) {
    const char* value = std::getenv(name);
    return value == nullptr ? std::nullopt : std::optional<std::string>(value);
}

}  // namespace

unsigned cpu_budget(const CpuBudgetInputs& inputs) {
    unsigned budget = inputs.affinity && *inputs.affinity > 0 ? *inputs.affinity : inputs.hardware;
    budget = std::max(1u, budget);
    if (const auto omp = positive_count(inputs.omp_threads)) {
        return std::min(budget, *omp);
    }
    if (const auto slurm = positive_count(inputs.slurm_cpus)) {
        return std::min(budget, *slurm);
    }
    return budget;
}

CpuBudgetInputs current_cpu_budget_inputs() {
    CpuBudgetInputs inputs;
    cpu_set_t mask;
    CPU_ZERO(&mask);
    if (sched_getaffinity(0, sizeof(mask), &mask) == 0) {
        inputs.affinity = static_cast<unsigned>(CPU_COUNT(&mask));
    }
    inputs.omp_threads = environment("OMP_NUM_THREADS");
    inputs.slurm_cpus = environment("SLURM_CPUS_PER_TASK");
    inputs.hardware = std::thread::hardware_concurrency();
    return inputs;
}

unsigned usable_threads() {
    return cpu_budget(current_cpu_budget_inputs());
}

}  // namespace sgmp
