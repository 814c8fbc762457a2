#pragma once
/// @file run_job.hpp
/// One job of a sweep in memory: the pack made by its parameters and seed (exactly what
/// `sgmp pack` makes from the same options), and its summary row with the metrics measured
/// in process by the measure the front end gives (sgmp/app gives sgmp-compare's).

#include <functional>
#include <string>
#include <vector>

#include "sgmp/batch/plan.hpp"
#include "sgmp/batch/summary.hpp"
#include "sgmp/pack/pack.hpp"

namespace sgmp::batch {

/// The metric fields of one pack, one per metric column of the SummarySchema.
using MeasureFields = std::function<std::vector<std::string>(const Pack& pack)>;

struct JobOptions {
    MeasureFields measure;  // empty: the packs are not measured
};

struct JobResult {
    Pack pack;
    SummaryRow row;
};

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
