#pragma once
/// @file parallel.hpp
/// Deterministic parallel loops. Work is cut into chunks whose boundaries depend only on
/// the problem size, never on the number of threads; each chunk is processed serially and
/// the per-chunk results are folded in chunk order. Floating-point sums therefore come out
/// bit-identical whatever the thread count.

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

namespace sgmp::metrics {

/// Every loop takes its worker threads from its caller (MeasureOptions::threads and the
/// options it hands down): `threads` > 0 is that many; 0 means the CPUs the process may use
/// (sgmp/pack/cpu_budget.hpp: affinity mask, OMP_NUM_THREADS, SLURM_CPUS_PER_TASK).
unsigned resolved_threads(unsigned threads);

/// sgmp::parallel_for (sgmp/pack/parallel.hpp) on resolved_threads(threads) threads.
void parallel_for(unsigned threads, std::size_t count,
                  const std::function<void(std::size_t)>& task);

/// Folds body(partial, begin, end), on `threads` workers, over fixed chunks of `chunk` items of [0,
/// n): each chunk starts from `zero`, and the chunk partials are combined with fold(total, partial)
/// in chunk order.
template <class Partial, class Body, class Fold>
Partial chunked_reduce(unsigned threads, std::size_t n, std::size_t chunk, const Partial& zero,
                       Body body, Fold fold) {
    const std::size_t chunks = chunk == 0 ? 0 : (n + chunk - 1) / chunk;
    std::vector<Partial> partials(chunks, zero);
    parallel_for(threads, chunks, [&](std::size_t c) {
        body(partials[c], c * chunk, std::min(n, (c + 1) * chunk));
    });
    Partial total = zero;
    for (const Partial& partial : partials) {
        fold(total, partial);
    }
    return total;
}

}  // namespace sgmp::metrics
