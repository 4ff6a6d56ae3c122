#pragma once
// Runs a command line in a shell and captures its exit code and output (stdout and stderr together).
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace gps::test {

struct CommandResult {
  int exit_code = -1;
  std::string output;
};

inline CommandResult run_command(const std::string& command) {
  CommandResult r;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline std::string gpsurf(const std::string& args) { return std::string(GPSURF_BINARY) + " " + args; }

}  // namespace gps::test
