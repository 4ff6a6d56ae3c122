#pragma once
// Running a program as a child process, its output discarded, for its exit code and its peak
// memory (the kernel's maximum resident set size of the child).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace gps::test {

struct MeasuredRun {
  int exit_code = -1;
  long peak_kb = 0;  // the child's maximum resident set size
};

/// Runs `argv` (the program first); with `loader_trace`, the dynamic loader writes every library
/// it loads (linked or opened later) to files named loader_trace.PID (glibc's LD_DEBUG=files).
inline MeasuredRun run_measured(const std::vector<std::string>& argv, const std::string& loader_trace = "") {
  std::fflush(stdout);  // or the child would print what is buffered again
  const pid_t child = ::fork();
  if (child == 0) {
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    if (!loader_trace.empty()) {
      ::setenv("LD_DEBUG", "files", 1);
      ::setenv("LD_DEBUG_OUTPUT", loader_trace.c_str(), 1);
    }
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr)) ::_exit(126);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  int status = 0;
  rusage usage{};
  ::wait4(child, &status, 0, &usage);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, usage.ru_maxrss};
}

}  // namespace gps::test
