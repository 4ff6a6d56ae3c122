#pragma once
// Runs a command line in a shell and captures its exit code and output (stdout and stderr together). A command
// that dies of a signal (a shell exit of 128 or more) has its output written to stderr as well, so that a crash
// seen once in CI keeps its stack in the test's log even where the test does not print the output.
#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
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
  if (r.exit_code >= 128 || r.exit_code < 0)
    std::fprintf(stderr, "[run_command] `%s` ended with %d (a signal); its output:\n%s\n", command.c_str(), r.exit_code,
                 r.output.c_str());
  return r;
}

inline std::string gpsurf(const std::string& args) { return std::string(GPSURF_BINARY) + " " + args; }

/// The number of lines of a command's output (its newlines).
inline size_t line_count(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

/// A file's bytes ("" where it cannot be read).
inline std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace gps::test
