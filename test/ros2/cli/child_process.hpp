#pragma once
// A command run in the background with its output in a file: waited for with a timeout, and
// killed when the test is done with it (or failed before), so that no test leaves a process.

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>

extern char** environ;

namespace facet::test {

class ChildProcess {
 public:
  // Runs `command` with /bin/sh, stdout and stderr into `log`.
  ChildProcess(const std::string& command, const std::filesystem::path& log) {
    const std::string shell = "exec " + command + " > '" + log.string() + "' 2>&1";
    const char* argv[] = {"/bin/sh", "-c", shell.c_str(), nullptr};
    if (posix_spawn(&pid_, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ) != 0) {
      pid_ = -1;
    }
  }
  ~ChildProcess() { kill(SIGKILL); }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool started() const { return pid_ > 0; }

  // The exit code (or -signal) once it ended, nothing if it still runs after `timeout_s`.
  std::optional<int> wait(double timeout_s) {
    if (status_) return status_;
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(timeout_s));
    while (pid_ > 0) {
      int status = 0;
      const pid_t done = waitpid(pid_, &status, WNOHANG);
      if (done == pid_) {
        status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
        pid_ = -1;
        return status_;
      }
      if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return status_;
  }

  // Sends `signal` and reaps the process; its exit is then what wait() returns.
  void kill(int signal) {
    if (pid_ <= 0) return;
    ::kill(pid_, signal);
    wait(10.0);
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      wait(10.0);
    }
  }

 private:
  pid_t pid_ = -1;
  std::optional<int> status_;
};

}  // namespace facet::test
