#include "sgmp/compare/parallel.hpp"

#include "sgmp/pack/cpu_budget.hpp"

#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace sgmp::compare {
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
    const std::size_t workers = std::min<std::size_t>(thread_count(), count);
    if (workers <= 1) {
        for (std::size_t i = 0; i < count; ++i) {
            task(i);
        }
        return;
    }
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr first_error;
    std::mutex error_mutex;
    const auto work = [&] {
        while (!failed) {
            const std::size_t i = next++;
            if (i >= count) {
                return;
            }
            try {
                task(i);
            } catch (...) {
                const std::lock_guard lock(error_mutex);
                if (!first_error) {
                    first_error = std::current_exception();
                }
                failed = true;
            }
        }
    };
    std::vector<std::thread> threads;
    threads.reserve(workers - 1);
    for (std::size_t t = 1; t < workers; ++t) {
        threads.emplace_back(work);
    }
    work();
    for (auto& thread : threads) {
        thread.join();
    }
    if (first_error) {
        std::rethrow_exception(first_error);
    }
}

}  // namespace sgmp::compare
