// gpsurf-render: the commands that need GL or OpenImageIO (bench, render, diff), which gpsurf runs
// in its own place with the same arguments (gl_commands.h); its messages are gpsurf's.
#include <CLI/CLI.hpp>

#include <string>

#include "app/commands.h"
#include "app/crash_stack.h"
#include "app/run_command_line.h"
#include "core/version.h"
#include "core/support/freed_memory.h"

int main(int argc, char** argv) {
  gps::report_crash_stack_if_asked("gpsurf");
  gps::keep_freed_memory();
  CLI::App app{"gpsurf: Gaussian-product subdivision surfaces (the commands that render)"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help on every subcommand");
  app.set_version_flag("--version", std::string("gpsurf ") + gps::kVersion);
  gps::add_bench_command(app);
  gps::add_render_command(app);
  gps::add_diff_command(app);
  return gps::run_command_line(app, argc, argv);
}
