#pragma once
// Runs a program as a child process with a changed environment and collects its stdout
// (stderr passes through), killing it after a time limit.
#include <optional>
#include <string>
#include <vector>

namespace pineda::bench {

struct EnvChange {
  std::string name;
  std::optional<std::string> value;  // nullopt: remove the variable
};

struct ChildOutcome {
  bool succeeded = false;  // exited with status 0 in time
  std::string output;      // everything it wrote to stdout
  std::string failure;     // why it did not succeed
};

ChildOutcome runChild(const std::string& program, const std::vector<std::string>& args,
                      const std::vector<EnvChange>& env, int timeoutSeconds);

// This executable's absolute path (from /proc/self/exe).
std::string selfExecutable();

}  // namespace pineda::bench
