#pragma once
/// @file executor.hpp
/// Running a list of independent jobs on worker threads. Results land by job position, so
/// what comes out does not depend on which thread ran which job or when; the calling
/// thread only reports progress.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace sgmp::batch {

/// Called with (jobs done, seconds since the start).
using ProgressReport = std::function<void(std::size_t, double)>;

/// Runs work(i) for every i in [0, count) on `threads` workers (at least one) and returns
/// the results in position order. Calls `report` every `interval` seconds (interval > 0)
/// while jobs run. The first exception a job throws stops the other workers from taking
/// new jobs and is rethrown once they have all stopped.
std::vector<std::string> run_jobs(std::size_t count, unsigned threads,
                                  const std::function<std::string(std::size_t)>& work,
                                  double interval, const ProgressReport& report);

}  // namespace sgmp::batch
