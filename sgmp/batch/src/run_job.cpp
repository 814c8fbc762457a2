#include "sgmp/batch/run_job.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/engine/pack_parameters.hpp"

namespace sgmp::batch {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

/// A job's row: its values, where a parameter left blank for its default by context (the
/// relaxation's schedule, by mode; the sweep stages, by arrangement) shows the value the pack
/// ran, as its header records it.
SummaryRow base_row(const Plan& plan, std::size_t job, const Pack& pack, const std::string& path) {
    SummaryRow row;
    row.job = job;
    row.values = plan.values(job);
    const auto& table = parameters();
    for (std::size_t i = 0; i < table.size(); ++i) {
        const auto recorded = pack.metadata.get(table[i].name);
        if (row.values[i].empty() && recorded &&
            engine::find_pack_parameter(table[i].name)->unset_by_default) {
            row.values[i] = *recorded;
        }
    }
    row.seed = plan.seed(job);
    row.path = path;
    return row;
}

void add_metrics(SummaryRow& row, const Pack& pack, const JobOptions& options) {
    if (!options.measure) {
        return;
    }
    const auto start = Clock::now();
    row.metric_fields = options.measure(pack);
    row.measure_seconds = since(start);
}

}  // namespace

JobResult run_job(const Plan& plan, std::size_t job, const JobOptions& options,
                  const std::string& path) {
    const engine::PackRequest request =
        to_request(plan.values(job), plan.seed(job), plan.distribution_files);
    JobResult result;
    const auto start = Clock::now();
    result.pack = engine::make_pack(request);
    result.row = base_row(plan, job, result.pack, path);
    result.row.seconds = since(start);
    add_metrics(result.row, result.pack, options);
    return result;
}

SummaryRow reused_row(const Plan& plan, std::size_t job, const Pack& pack,
                      const JobOptions& options, const std::string& path) {
    const ParameterValues& values = plan.values(job);
    const auto expect = [&](const std::string& key, const std::string& value) {
        const auto found = pack.metadata.get(key);
        if (!found || *found != value) {
            throw std::invalid_argument(path + ": exists but holds another pack (" + key + " " +
                                        (found ? *found : std::string("missing")) + ", the job " +
                                        value + "); pass --force to remake it");
        }
    };
    expect("generator", "sgmp");
    expect("count", values[parameter_index("count")]);
    expect("arrangement", values[parameter_index("arrangement")]);
    expect("seed", std::to_string(plan.seed(job)));
    SummaryRow row = base_row(plan, job, pack, path);
    add_metrics(row, pack, options);
    return row;
}

}  // namespace sgmp::batch
