#pragma once
/// @file run_job.hpp
/// One job of a sweep in memory: the pack made by its parameters and seed (exactly what
/// `sgmp pack` makes from the same options), and its summary row with the metrics measured
/// in process by sgmp_metrics (`sgmp-compare measure`'s definitions and defaults).

#include <string>

#include "sgmp/batch/plan.hpp"
#include "sgmp/batch/summary.hpp"
#include "sgmp/pack/pack.hpp"

namespace sgmp::batch {

struct JobOptions {
    bool measure = false;
    bool voronoi = false;  // the Voronoi local φ too (its own, slower stage)
};

struct JobResult {
    Pack pack;
    SummaryRow row;
};

/// g(r) is histogrammed out to this many d for the summary: the split ratio's windows end at
/// 2.05 d, and the pair search grows as the range cubed (5 d, measure's default, costs eight
/// times as much at N = 10^4). The split ratio's density ρ cancels in the ratio, so it
/// equals `measure`'s up to rounding (1e-15 relative, checked on a 10^4 pack).
inline constexpr double kSummaryGrRange = 2.1;

/// The metrics of `pack` (summary.hpp), as `sgmp-compare measure` defines them.
PackMetrics measure_pack(const Pack& pack, bool voronoi);

/// Makes job `job` of `plan`; `path` is recorded in the row. Throws std::invalid_argument
/// for an invalid combination (make_plan has already refused those).
JobResult run_job(const Plan& plan, std::size_t job, const JobOptions& options,
                  const std::string& path);

/// The row of a pack made earlier (reused by --skip-existing): no packing time; measured
/// when options.measure. Throws std::invalid_argument when the pack's header disagrees
/// with the job's count, arrangement or seed.
SummaryRow reused_row(const Plan& plan, std::size_t job, const Pack& pack,
                      const JobOptions& options, const std::string& path);

}  // namespace sgmp::batch
