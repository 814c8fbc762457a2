#include "sgmp/metrics/parallel.hpp"

#include "sgmp/pack/cpu_budget.hpp"
#include "sgmp/pack/parallel.hpp"

namespace sgmp::metrics {

unsigned resolved_threads(unsigned threads) {
    return threads > 0 ? threads : sgmp::usable_threads();
}

void parallel_for(unsigned threads, std::size_t count,
                  const std::function<void(std::size_t)>& task) {
    sgmp::parallel_for(resolved_threads(threads), count, task);
}

}  // namespace sgmp::metrics
