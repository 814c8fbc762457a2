#pragma once
/// @file cpu_budget.hpp
/// How many threads a tool may start: the CPUs the scheduler gave the process, not the
/// machine's. The count is the size of the CPU affinity mask (`sched_getaffinity`, which
/// `taskset`, cgroups, Slurm and `mpirun --bind-to` set), else
/// `std::thread::hardware_concurrency()`; a valid `OMP_NUM_THREADS` (else a valid
/// `SLURM_CPUS_PER_TASK`) lowers it further, never raises it above the mask. Always ≥ 1.

#include <optional>
#include <string>

namespace sgmp {

/// What the budget is computed from (each absent when unknown or unset).
struct CpuBudgetInputs {
    std::optional<unsigned> affinity;        // CPUs in the affinity mask
    std::optional<std::string> omp_threads;  // OMP_NUM_THREADS as set
    std::optional<std::string> slurm_cpus;   // SLURM_CPUS_PER_TASK as set
    unsigned hardware = 0;                   // hardware_concurrency (0: unknown)
};

/// The usable thread count for `inputs`. An environment value counts only when it is a
/// whole number ≥ 1 (OMP_NUM_THREADS may be a list such as "4,2": its first entry counts).
unsigned cpu_budget(const CpuBudgetInputs& inputs);

/// The inputs of this process (its affinity mask and environment).
CpuBudgetInputs current_cpu_budget_inputs();

/// cpu_budget(current_cpu_budget_inputs()).
unsigned usable_threads();

}  // namespace sgmp
