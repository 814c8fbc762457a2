#include "run_program.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace sgmp::reference::testing {

ProgramRun run_program(const std::string& executable, const ProgramOptions& options) {
    const std::filesystem::path err = fresh_directory("sgmp-ref-run") / "stderr.txt";
    const pid_t pid = fork();
    if (pid < 0) {
        throw std::runtime_error("fork failed");
    }
    if (pid == 0) {
        const int fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(fd, STDERR_FILENO);
        const int null_out = open("/dev/null", O_WRONLY);
        dup2(null_out, STDOUT_FILENO);
        if (options.path) {
            setenv("PATH", options.path->c_str(), 1);
        }
        std::vector<char*> argv{const_cast<char*>(executable.c_str())};
        for (const auto& a : options.args) {
            argv.push_back(const_cast<char*>(a.c_str()));
        }
        argv.push_back(nullptr);
        execv(executable.c_str(), argv.data());
        _exit(127);
    }
    int status = 0;
    bool signalled = false;
    while (waitpid(pid, &status, WNOHANG) != pid) {
        if (options.signal_when_exists && !signalled &&
            std::filesystem::exists(*options.signal_when_exists)) {
            kill(pid, options.signal);
            signalled = true;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ProgramRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::ifstream in(err);
    std::ostringstream text;
    text << in.rdbuf();
    run.stderr_text = text.str();
    std::filesystem::remove_all(err.parent_path());
    return run;
}

std::filesystem::path fresh_directory(const std::string& stem) {
    std::string pattern = (std::filesystem::temp_directory_path() / (stem + "-XXXXXX")).string();
    if (mkdtemp(pattern.data()) == nullptr) {
        throw std::runtime_error("mkdtemp failed");
    }
    return pattern;
}

void write_script(const std::filesystem::path& path, const std::string& body) {
    {
        std::ofstream out(path);
        out << "#!/bin/bash\n" << body;
    }
    std::filesystem::permissions(path, std::filesystem::perms::owner_all |
                                           std::filesystem::perms::group_read |
                                           std::filesystem::perms::group_exec);
}

}  // namespace sgmp::reference::testing
