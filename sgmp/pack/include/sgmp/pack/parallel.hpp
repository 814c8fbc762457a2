#pragma once
/// @file parallel.hpp
/// The one worker loop of the testbed: task(i) for every i in [0, count) on a given number
/// of threads. Callers cut their work into items whose boundaries depend only on the
/// problem size, never on the thread count, and combine the items' results in item order,
/// so what they compute does not depend on how many threads ran it.

#include <cstddef>
#include <functional>

namespace sgmp {

/// Runs task(i) for every i in [0, count) on `workers` threads (the caller's among them;
/// any order). The first exception thrown by a task is rethrown after all workers
/// stopped; items not yet started then never run.
void parallel_for(unsigned workers, std::size_t count,
                  const std::function<void(std::size_t)>& task);

}  // namespace sgmp
