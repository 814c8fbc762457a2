#include "sgmp/metrics/parallel.hpp"

#include "sgmp/pack/cpu_budget.hpp"

#include <atomic>

#include "sgmp/pack/parallel.hpp"

namespace sgmp::metrics {
namespace {
std::atomic<unsigned> requested_threads{0};
}  // namespace

void set_thread_count(unsigned count) {
    requested_threads = count;
}

unsigned thread_count() {
    const unsigned requested = requested_threads;
    if (requested > 0) {
        return requested;
    }
    return sgmp::usable_threads();
}

void parallel_for(std::size_t count, const std::function<void(std::size_t)>& task) {
    sgmp::parallel_for(thread_count(), count, task);
}

}  // namespace sgmp::metrics
