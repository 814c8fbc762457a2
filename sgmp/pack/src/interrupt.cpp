#include "sgmp/pack/interrupt.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <iostream>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

namespace sgmp {
namespace fs = std::filesystem;

namespace {

std::mutex registry_mutex;
std::multiset<fs::path>& registry() {
    static std::multiset<fs::path> paths;
    return paths;
}

/// Removes every registered temporary; the caller holds registry_mutex.
void sweep_registry() {
    for (const auto& path : registry()) {
        remove_temporary(path);
    }
}

int signal_pipe[2] = {-1, -1};

/// The signals that stop a program with its temporaries removed: Ctrl-C, kill, a closed
/// terminal (SIGHUP) and Ctrl-\ (SIGQUIT).
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

const char* signal_name(int number) {
    switch (number) {
        case SIGINT:
            return "SIGINT";
        case SIGTERM:
            return "SIGTERM";
        case SIGHUP:
            return "SIGHUP";
        case SIGQUIT:
            return "SIGQUIT";
        default:
            return "a signal";
    }
}

extern "C" void on_signal(int number) {
    const int saved = errno;
    const unsigned char byte = static_cast<unsigned char>(number);
    (void)!::write(signal_pipe[1], &byte, 1);
    errno = saved;
}

void watch(const std::string& program, const std::function<bool()>& on_interrupt) {
    while (true) {
        unsigned char byte = 0;
        const ssize_t got = ::read(signal_pipe[0], &byte, 1);
        if (got < 0 && errno == EINTR) {
            continue;
        }
        if (got != 1) {
            return;
        }
        if (on_interrupt && on_interrupt()) {
            continue;  // the program stops by itself
        }
        // The registry stays locked until the process ends: a thread that is about to
        // create a temporary (TemporaryGuard creates it under this lock) waits instead of
        // leaving one behind after the sweep.
        registry_mutex.lock();
        sweep_registry();
        const std::string message = program + ": interrupted by " + signal_name(byte) +
                                    "; its temporary files are removed\n";
        (void)!::write(STDERR_FILENO, message.data(), message.size());
        ::_exit(kInterruptedStatus);
    }
}

}  // namespace

void install_interrupt_handler(const std::string& program, std::function<bool()> on_interrupt) {
    if (signal_pipe[0] >= 0) {
        return;
    }
    if (::pipe2(signal_pipe, O_CLOEXEC) != 0) {
        throw std::runtime_error(program +
                                 ": cannot create the signal pipe: " + std::strerror(errno));
    }
    std::thread(watch, program, std::move(on_interrupt)).detach();
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    for (const int number : kStopSignals) {
        sigaction(number, &action, nullptr);
    }
    // Past `ulimit -f` a write then fails with EFBIG, reported and cleaned up like ENOSPC,
    // instead of the signal killing the process with its temporaries in place.
    std::signal(SIGXFSZ, SIG_IGN);
}

void remove_registered_temporaries() {
    const std::lock_guard lock(registry_mutex);
    sweep_registry();
}

void run_uninterrupted(const std::function<void()>& work) {
    // The watcher sweeps and exits under this lock (watch), so it waits for `work`.
    const std::lock_guard lock(registry_mutex);
    work();
}

TemporaryGuard::TemporaryGuard(fs::path path, const std::function<void()>& create)
    : path_(std::move(path)) {
    const std::lock_guard lock(registry_mutex);
    registry().insert(path_);
    if (create) {
        try {
            create();
        } catch (...) {
            registry().erase(registry().find(path_));
            throw;
        }
    }
}

TemporaryGuard::~TemporaryGuard() {
    const std::lock_guard lock(registry_mutex);
    const auto found = registry().find(path_);
    if (found != registry().end()) {
        registry().erase(found);
    }
}

void remove_temporary(const fs::path& path) {
    std::error_code ignored;
    fs::remove_all(path, ignored);
}

}  // namespace sgmp
