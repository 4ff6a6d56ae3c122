// gpsurf: the command line. Each subcommand lives in its own cmd_*.cpp; errors are caught once here.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

#include "app/commands.h"
#include "core/mesh/error.h"
#include "core/version.h"
#include "core/support/freed_memory.h"

int main(int argc, char** argv) {
  gps::keep_freed_memory();
  CLI::App app{"gpsurf: Gaussian-product subdivision surfaces"};
  app.require_subcommand(1);
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return "gpsurf: " + std::string(e.what()) + "\n"; });
  app.set_help_all_flag("--help-all", "help on every subcommand");
  app.set_version_flag("--version", std::string("gpsurf ") + gps::kVersion);
  gps::add_info_command(app);
  gps::add_sample_command(app);
  gps::add_infer_command(app);
  gps::add_subdivide_command(app);
  gps::add_tessellate_command(app);
#ifdef GPSURF_WITH_GL
  gps::add_bench_command(app);
  gps::add_render_command(app);
  gps::add_diff_command(app);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help or the parse error
    return code == 0 ? 0 : 2;
  } catch (const gps::Error& e) {
    std::cerr << "gpsurf: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "gpsurf: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
