#include "app/gl_commands.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>

#include "core/support/freed_memory.h"
#include "core/support/quoted_text.h"

namespace gps {

namespace {

[[noreturn]] void refuse(const std::string& message) {
  std::cerr << "gpsurf: " << escaped(message) << "\n";
  std::exit(1);
}

}  // namespace

#ifdef GPSURF_WITH_GL

void add_gl_command_entries(CLI::App& app) {
  for (const GlCommand& command : kGlCommands)
    app.add_subcommand(command.name, command.summary)->allow_extras()->footer("Its options: gpsurf " + std::string(command.name) + " --help");
}

namespace {

// The folder of the running program: /proc/self/exe, or argv[0] where that holds a path.
std::filesystem::path program_folder(const char* argv0) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) return self.parent_path();
  return std::filesystem::path(argv0).parent_path();
}

}  // namespace

void run_gl_command_if_named(int argc, char** argv) {
  if (argc < 2 || *gl_command_summary(argv[1]) == '\0') return;
  const std::filesystem::path folder = program_folder(argv[0]);
  // In a build tree beside gpsurf; installed, in the libexec folder (GPSURF_RENDER_FOLDER, from bin/).
  const std::filesystem::path candidates[] = {folder / "gpsurf-render",
                                              (folder / GPSURF_RENDER_FOLDER / "gpsurf-render").lexically_normal()};
  // Under a software driver the GL buffers are the process's heap: hundreds of MB for a large mesh.
  huge_page_heap_for_next_program();
  for (const std::filesystem::path& program : candidates) {
    ::execv(program.c_str(), argv);  // returns only where it failed
    if (errno != ENOENT)
      refuse(std::string(argv[1]) + ": cannot run " + program.string() + ": " + std::strerror(errno));
  }
  refuse(std::string(argv[1]) + " runs in gpsurf-render, which is neither in " + candidates[0].parent_path().string() +
         " nor in " + candidates[1].parent_path().string());
}

#else

void add_gl_command_entries(CLI::App&) {}

void run_gl_command_if_named(int argc, char** argv) {
  if (argc >= 2 && *gl_command_summary(argv[1]) != '\0')
    refuse(std::string(argv[1]) + " needs GL, and this gpsurf was built without it (GPSURF_BUILD_GL=OFF)");
}

#endif

}  // namespace gps
