#pragma once
/// @file output_lock.hpp
/// One writer per output: an advisory lock that two processes writing one file (two
/// batches with one summary) take, so that the second is refused at its start instead of
/// losing the first's content when the last rename wins.
///
/// The lock is a POSIX record lock (fcntl F_SETLK, which NFS carries through its lock
/// manager) on the sibling file `.NAME.lock`, holding the holder's "HOST pid PID" for the
/// refusal. It dies with its process, so a killed holder never blocks a later run; the
/// file is removed when the lock is released.

#include <filesystem>
#include <memory>

#include "sgmp/pack/interrupt.hpp"

namespace sgmp {

class OutputLock {
  public:
    /// Takes the lock of `target` or throws std::runtime_error "<target>: is being written
    /// by another process (HOST pid PID)"; a lock file that cannot be made throws too.
    explicit OutputLock(const std::filesystem::path& target);
    ~OutputLock();  // removes the lock file and releases the lock
    OutputLock(const OutputLock&) = delete;
    OutputLock& operator=(const OutputLock&) = delete;

  private:
    std::filesystem::path path_;
    int fd_ = -1;
    std::unique_ptr<TemporaryGuard> guard_;  // removes the lock file on an interrupt
};

}  // namespace sgmp
