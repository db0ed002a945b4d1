#pragma once
// Runs the shadelab binary as a user would (SHADELAB_BINARY, set by CMake for
// the test programs that need it), capturing what it prints and its exit code.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace shadelab::test {

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

// Runs a shell command line as given (add 2>&1 to capture stderr too).
inline CommandResult runShell(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append(buffer.data(), n);
  int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// `environment` is prefixed to the command line (e.g. "cd DIR && VAR=1").
inline CommandResult run(const std::string& arguments, const std::string& environment = "") {
  return runShell(environment + " " + std::string(SHADELAB_BINARY) + " " + arguments + " 2>&1");
}

}  // namespace shadelab::test
