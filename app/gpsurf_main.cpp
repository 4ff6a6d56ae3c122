// gpsurf: the command line. Each subcommand lives in its own cmd_*.cpp; errors are caught once
// (run_command_line.cpp). The GL commands run in gpsurf-render (gpsurf_render_main.cpp), so that
// the others load neither GL nor OpenImageIO.
#include <CLI/CLI.hpp>

#include <string>

#include "app/commands.h"
#include "app/crash_stack.h"
#include "app/gl_commands.h"
#include "app/run_command_line.h"
#include "core/version.h"
#include "core/support/freed_memory.h"

int main(int argc, char** argv) {
  gps::report_crash_stack_if_asked("gpsurf");
  gps::run_gl_command_if_named(argc, argv);
  gps::keep_freed_memory();
  CLI::App app{"gpsurf: Gaussian-product subdivision surfaces"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help on every subcommand");
  app.set_version_flag("--version", std::string("gpsurf ") + gps::kVersion);
  gps::add_info_command(app);
  gps::add_sample_command(app);
  gps::add_infer_command(app);
  gps::add_subdivide_command(app);
  gps::add_edit_command(app);
  gps::add_tessellate_command(app);
  gps::add_simplify_command(app);
  gps::add_compare_command(app);
  gps::add_fit_command(app);
  gps::add_gl_command_entries(app);
  return gps::run_command_line(app, argc, argv);
}
