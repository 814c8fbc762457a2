#pragma once
/// @file interrupt.hpp
/// Ctrl-C (SIGINT), SIGTERM, SIGHUP (a closed terminal) and SIGQUIT (Ctrl-\) for the
/// command-line tools: a program's temporaries are removed and it exits with status 130, so an
/// interrupted command leaves no
/// `.NAME.tmp-PID.HOST` file or directory behind.
///
/// The signal handler only writes the signal's number to a pipe; a watcher thread reads
/// it and does the work outside signal context. Child processes get the default
/// disposition back at exec.

#include <filesystem>
#include <functional>
#include <string>

namespace sgmp {

/// Exit status of a program stopped by SIGINT, SIGTERM, SIGHUP or SIGQUIT.
inline constexpr int kInterruptedStatus = 130;

/// Installs the handlers. On a signal, `on_interrupt` (when given) is called from the
/// watcher thread; when it returns true the program has promised to stop by itself (it
/// polls a flag), otherwise every registered temporary is removed, "PROGRAM: interrupted
/// by SIGINT" is printed and the process exits with kInterruptedStatus. SIGXFSZ is
/// ignored, so a write past the file-size limit fails like a full disk (one line, status 1,
/// no temporary left).
void install_interrupt_handler(const std::string& program, std::function<bool()> on_interrupt = {});

/// Removes every registered temporary now (what an interrupt does before exiting).
void remove_registered_temporaries();

/// Runs `work` with interrupts held off: a SIGINT or SIGTERM that comes meanwhile removes
/// the temporaries and exits only after `work` returns. For steps that must not be cut in
/// two, such as renaming a pair of files into place. `work` must not create or end a
/// TemporaryGuard.
void run_uninterrupted(const std::function<void()>& work);

/// Registers a temporary file or directory for removal on interrupt while it lives.
/// `create` (when given) makes it under the registry's lock, so an interrupt either
/// removes it or comes before it exists: none is left behind by a thread racing the exit.
class TemporaryGuard {
  public:
    explicit TemporaryGuard(std::filesystem::path path, const std::function<void()>& create = {});
    ~TemporaryGuard();
    TemporaryGuard(const TemporaryGuard&) = delete;
    TemporaryGuard& operator=(const TemporaryGuard&) = delete;

  private:
    std::filesystem::path path_;
};

/// Removes a temporary file or directory tree, ignoring errors.
void remove_temporary(const std::filesystem::path& path);

}  // namespace sgmp
