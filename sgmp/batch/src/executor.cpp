#include "sgmp/batch/executor.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace sgmp::batch {

std::vector<std::string> run_jobs(std::size_t count, unsigned threads,
                                  const std::function<std::string(std::size_t)>& work,
                                  double interval, const ProgressReport& report) {
    std::vector<std::string> results(count);
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr first_error;
    std::mutex mutex;
    std::condition_variable finished;
    std::size_t done = 0;
    std::size_t running = std::max<std::size_t>(1, std::min<std::size_t>(threads, count));
    const auto worker = [&] {
        while (!failed) {
            const std::size_t i = next++;
            if (i >= count) {
                break;
            }
            try {
                results[i] = work(i);
                const std::lock_guard lock(mutex);
                ++done;
            } catch (...) {
                const std::lock_guard lock(mutex);
                if (!first_error) {
                    first_error = std::current_exception();
                }
                failed = true;
            }
        }
        const std::lock_guard lock(mutex);
        --running;
        finished.notify_all();
    };
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (std::size_t t = 0, n = running; t < n; ++t) {
        pool.emplace_back(worker);
    }
    {
        std::unique_lock lock(mutex);
        const auto period = std::chrono::duration<double>(interval > 0.0 ? interval : 1e9);
        while (running > 0) {
            if (!finished.wait_for(lock, period, [&] { return running == 0; }) && interval > 0.0 &&
                report) {
                const double seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                const std::size_t now_done = done;
                lock.unlock();
                report(now_done, seconds);
                lock.lock();
            }
        }
    }
    for (auto& thread : pool) {
        thread.join();
    }
    if (first_error) {
        std::rethrow_exception(first_error);
    }
    return results;
}

}  // namespace sgmp::batch
