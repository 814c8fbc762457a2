#include "sgmp/pack/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace sgmp {
namespace {

using Clock = std::chrono::steady_clock;

/// In the child: own process group, output to the pipe, then exec. Never returns.
[[noreturn]] void exec_child(const ChildOptions& options, int write_end, pid_t parent) {
    setpgid(0, 0);
    // Killed with its parent, even by SIGKILL, so it never outlives sgmp-reference (mpirun
    // in turn ends its ranks when it dies). The parent may have died before this line.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) {
        _exit(127);
    }
    dup2(write_end, STDOUT_FILENO);
    dup2(write_end, STDERR_FILENO);
    close(write_end);
    const int null_in = open("/dev/null", O_RDONLY);
    if (null_in >= 0) {
        dup2(null_in, STDIN_FILENO);
        close(null_in);
    }
    if (!options.working_directory.empty() && chdir(options.working_directory.c_str()) != 0) {
        const std::string message = "cannot enter " + options.working_directory.string() + "\n";
        (void)!write(STDERR_FILENO, message.data(), message.size());
        _exit(127);
    }
    std::vector<char*> argv;
    for (const auto& arg : options.argv) {
        argv.push_back(const_cast<char*>(arg.c_str()));
    }
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    const std::string message =
        "cannot run " + options.argv[0] + ": " + std::strerror(errno) + "\n";
    (void)!write(STDERR_FILENO, message.data(), message.size());
    _exit(127);
}

/// Splits a byte stream into lines.
class LineSplitter {
  public:
    explicit LineSplitter(const std::function<void(const std::string&)>& on_line)
        : on_line_(on_line) {}
    void feed(const char* data, std::size_t size) {
        for (std::size_t i = 0; i < size; ++i) {
            if (data[i] == '\n') {
                flush();
            } else if (data[i] != '\r') {
                partial_.push_back(data[i]);
            }
        }
    }
    void flush() {
        if (on_line_) {
            on_line_(partial_);
        }
        partial_.clear();
    }
    [[nodiscard]] bool pending() const { return !partial_.empty(); }

  private:
    const std::function<void(const std::string&)>& on_line_;
    std::string partial_;
};

/// Reads what is available now; returns false at end of file.
bool drain(int fd, LineSplitter& lines) {
    char buffer[8192];
    while (true) {
        const ssize_t got = read(fd, buffer, sizeof buffer);
        if (got > 0) {
            lines.feed(buffer, static_cast<std::size_t>(got));
            continue;
        }
        if (got == 0) {
            return false;
        }
        return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
    }
}

/// SIGTERM to the whole group, SIGKILL after a grace period; returns the wait status.
int end_group(pid_t pid) {
    kill(-pid, SIGTERM);
    const auto deadline = Clock::now() + std::chrono::seconds(3);
    int status = 0;
    while (Clock::now() < deadline) {
        if (waitpid(pid, &status, WNOHANG) == pid) {
            kill(-pid, SIGKILL);  // stragglers of the group (e.g. MPI ranks)
            return status;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    kill(-pid, SIGKILL);
    waitpid(pid, &status, 0);
    return status;
}

}  // namespace

ChildResult run_child(const ChildOptions& options,
                      const std::function<void(const std::string& line)>& on_line) {
    if (options.argv.empty()) {
        throw std::invalid_argument("run_child: empty command");
    }
    int fds[2];
    if (pipe(fds) != 0) {
        throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
    }
    const auto start = Clock::now();
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        throw std::runtime_error(std::string("cannot fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
        close(fds[0]);
        exec_child(options, fds[1], parent);
    }
    setpgid(pid, pid);  // also in the parent, so a kill right away reaches the group
    close(fds[1]);
    fcntl(fds[0], F_SETFL, fcntl(fds[0], F_GETFL) | O_NONBLOCK);

    LineSplitter lines(on_line);
    ChildResult result;
    bool open = true;
    int status = 0;
    bool reaped = false;
    while (!reaped) {
        if (open) {
            pollfd pfd{fds[0], POLLIN, 0};
            poll(&pfd, 1, 100);
            open = drain(fds[0], lines);
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        const bool stop = options.should_stop && options.should_stop();
        const bool late = options.timeout && Clock::now() - start > *options.timeout;
        if (stop || late) {
            status = end_group(pid);
            result.end = stop ? ChildEnd::stopped : ChildEnd::timed_out;
            reaped = true;
            break;
        }
        if (waitpid(pid, &status, WNOHANG) == pid) {
            reaped = true;
            // Children of the child may still hold the pipe: take what is there, no more.
            if (open) {
                drain(fds[0], lines);
            }
        }
    }
    close(fds[0]);
    if (lines.pending()) {
        lines.flush();
    }
    result.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (result.end == ChildEnd::exited) {
        if (WIFEXITED(status)) {
            result.exit_code = WEXITSTATUS(status);
        } else if (WIFSIGNALED(status)) {
            result.end = ChildEnd::signalled;
            result.signal = WTERMSIG(status);
        }
    }
    return result;
}

}  // namespace sgmp
