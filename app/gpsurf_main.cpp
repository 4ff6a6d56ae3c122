// gpsurf: the command line. Each subcommand lives in its own cmd_*.cpp; errors are caught once here.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <new>
#include <string>

#include "app/commands.h"
#include "core/io/quoted_text.h"
#include "core/mesh/error.h"
#include "core/version.h"
#include "core/support/freed_memory.h"

namespace {

// What the command that ran was given to read (its first positional argument, or its --script), for
// a message that must name it; the command's name where it has neither.
std::string input_of(const CLI::App& command) {
  for (const CLI::Option* option : command.get_options())
    if (option->get_positional() && option->count() > 0) return option->results().front();
  if (const CLI::Option* script = command.get_option_no_throw("--script"); script && script->count() > 0)
    return script->results().front();
  return command.get_name();
}

}  // namespace

int main(int argc, char** argv) {
  gps::keep_freed_memory();
  CLI::App app{"gpsurf: Gaussian-product subdivision surfaces"};
  app.require_subcommand(1);
  // Every message is escaped once more here, so that whatever it quotes it stays one harmless line.
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return "gpsurf: " + gps::escaped(e.what()) + "\n"; });
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
    std::cerr << "gpsurf: " << gps::escaped(e.what()) << "\n";
    return e.exit_code();
  } catch (const std::bad_alloc&) {
    const auto commands = app.get_subcommands();
    if (commands.empty()) {
      std::cerr << "gpsurf: out of memory\n";
    } else {
      std::cerr << "gpsurf: " << gps::escaped(input_of(*commands.front())) << ": out of memory in "
                << commands.front()->get_name() << "\n";
    }
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "gpsurf: " << gps::escaped(e.what()) << "\n";
    return 1;
  }
  return 0;
}
