#include "app/run_command_line.h"

#include <iostream>
#include <new>
#include <string>

#include "core/support/quoted_text.h"
#include "core/support/error.h"

namespace gps {

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

int run_command_line(CLI::App& app, int argc, char** argv) {
  // Every message is escaped once more here, so that whatever it quotes it stays one harmless line.
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return "gpsurf: " + escaped(e.what()) + "\n"; });
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help or the parse error
    return code == 0 ? 0 : 2;
  } catch (const Error& e) {
    std::cerr << "gpsurf: " << escaped(e.what()) << "\n";
    return e.exit_code();
  } catch (const std::bad_alloc&) {
    const auto commands = app.get_subcommands();
    if (commands.empty()) {
      std::cerr << "gpsurf: out of memory\n";
    } else {
      std::cerr << "gpsurf: " << escaped(input_of(*commands.front())) << ": out of memory in "
                << commands.front()->get_name() << "\n";
    }
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "gpsurf: " << escaped(e.what()) << "\n";
    return 1;
  }
  return 0;
}

}  // namespace gps
