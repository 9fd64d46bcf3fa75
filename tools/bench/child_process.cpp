#include "child_process.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace pineda::bench {

std::string selfExecutable() {
  std::error_code error;
  return std::filesystem::read_symlink("/proc/self/exe", error).string();
}

ChildOutcome runChild(const std::string& program, const std::vector<std::string>& args,
                      const std::vector<EnvChange>& env, int timeoutSeconds) {
  ChildOutcome outcome;
  int pipeFds[2];
  if (pipe(pipeFds) != 0) {
    outcome.failure = std::string("pipe: ") + std::strerror(errno);
    return outcome;
  }
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);

  const pid_t pid = fork();
  if (pid < 0) {
    outcome.failure = std::string("fork: ") + std::strerror(errno);
    close(pipeFds[0]);
    close(pipeFds[1]);
    return outcome;
  }
  if (pid == 0) {  // the parent has no other threads, so setenv after fork is safe
    dup2(pipeFds[1], STDOUT_FILENO);
    close(pipeFds[0]);
    close(pipeFds[1]);
    for (const EnvChange& change : env) {
      if (change.value)
        setenv(change.name.c_str(), change.value->c_str(), 1);
      else
        unsetenv(change.name.c_str());
    }
    execv(program.c_str(), argv.data());
    _exit(127);
  }
  close(pipeFds[1]);

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
  bool timedOut = false;
  char buffer[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timedOut = true;
      kill(pid, SIGKILL);
      break;
    }
    pollfd fd{pipeFds[0], POLLIN, 0};
    const int ready = poll(&fd, 1, int(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t got = read(pipeFds[0], buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;  // end of file: the child closed stdout (normally by exiting)
    outcome.output.append(buffer, std::size_t(got));
  }
  close(pipeFds[0]);

  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timedOut)
    outcome.failure = "timed out after " + std::to_string(timeoutSeconds) + " s";
  else if (WIFSIGNALED(status))
    outcome.failure = std::string("killed by signal ") + strsignal(WTERMSIG(status));
  else if (WEXITSTATUS(status) == 127)
    outcome.failure = "could not run " + program;
  else if (WEXITSTATUS(status) != 0)
    outcome.failure = "exit status " + std::to_string(WEXITSTATUS(status));
  else
    outcome.succeeded = true;
  return outcome;
}

}  // namespace pineda::bench
