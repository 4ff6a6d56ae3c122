#include "app/run_command_line.h"

#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

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

// Whether `app` or one of its subcommands has the long option `name` ("--weld") taking a value.
bool takes_value(const CLI::App& app, const std::string& name) {
  if (const CLI::Option* option = app.get_option_no_throw(name); option && option->get_type_size_max() > 0) return true;
  for (const CLI::App* command : app.get_subcommands({}))
    if (takes_value(*command, name)) return true;
  return false;
}

// The arguments with "--name=" (an empty value) as "--name" "": CLI11 drops an empty value after '='
// and reports the option's value as missing, in its own words; as two arguments the value reaches the
// option's check, which names the option and what is wrong with the text.
std::vector<std::string> empty_values_split(const CLI::App& app, int argc, char** argv) {
  std::vector<std::string> args;
  bool options_end = false;
  for (int i = 0; i < argc; ++i) {
    const std::string arg = argv[i];
    options_end = options_end || arg == "--";
    if (!options_end && i > 0 && arg.size() > 3 && arg.starts_with("--") && arg.ends_with("=") &&
        takes_value(app, arg.substr(0, arg.size() - 1))) {
      args.push_back(arg.substr(0, arg.size() - 1));
      args.emplace_back();
    } else {
      args.push_back(arg);
    }
  }
  return args;
}

// Names a word CLI11 would report in its own terms or behind another fault first: a command that is
// not one ("A subcommand is required"), an option the command does not know (after a missing input,
// "file is required"). Values, negative numbers among them, follow the options that take them.
void check_words(const CLI::App& app, const std::vector<std::string>& args) {
  const CLI::App* command = nullptr;
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--") return;
    if (command == nullptr) {
      if (arg.starts_with("-")) {
        if (app.get_option_no_throw(arg.substr(0, arg.find('='))) != nullptr) return;  // --help, --version: CLI11's
        throw usage_error("unknown option " + quoted_token(arg) + " (a command comes first: gpsurf --help lists them)");
      }
      try {
        command = app.get_subcommand(arg);
      } catch (const CLI::OptionNotFound&) {
        throw usage_error(quoted_token(arg) + " is not a command of gpsurf (gpsurf --help lists them)");
      }
      continue;
    }
    if (arg.size() < 2 || arg[0] != '-' || (arg[1] >= '0' && arg[1] <= '9') || arg[1] == '.') continue;
    const std::string name = arg.substr(0, arg.find('='));
    const CLI::Option* option = command->get_option_no_throw(name);
    if (option == nullptr) {
      if (name == "-h" || name == "--help" || name == "--help-all") return;
      throw usage_error("unknown option " + quoted_token(name) + " (gpsurf " + command->get_name() +
                        " --help lists them)");
    }
    if (option->get_type_size_max() > 0 && name.size() == arg.size()) ++i;  // its value, whatever it looks like
  }
}

}  // namespace

// A file that is not there, an option given twice, a value missing, words left over, options that
// exclude each other, a word not among the choices, something required.
std::string in_our_words(const std::string& message) {
  const std::string at_most = ": At Most 1 required but received ";
  if (const size_t at = message.find(at_most); at != std::string::npos)
    return message.substr(0, at) + " is given " + message.substr(at + at_most.size()) + " times; give it once";
  if (const std::string missing = ": File does not exist: "; message.find(missing) != std::string::npos)
    return message.substr(message.find(missing) + missing.size()) + ": no such file";
  if (const size_t at = message.find(": 1 required "); at != std::string::npos && message.ends_with(" missing"))
    return message.substr(0, at) + " needs a value after it";
  for (const std::string extra :
       {"The following argument was not expected: ", "The following arguments were not expected: "})
    if (message.starts_with(extra)) {
      std::string words;
      std::istringstream rest(message.substr(extra.size()));
      for (std::string word; rest >> word;)
        words = quoted_token(word) + (words.empty() ? "" : ", ") + words;  // CLI11 lists them last first
      return "more words than the command takes: " + words + " (its --help lists what it takes)";
    }
  if (const size_t at = message.find(" excludes "); at != std::string::npos && message.starts_with("-"))
    return message.substr(0, at) + " and " + message.substr(at + 10) + " exclude each other; give one of them";
  if (const size_t at = message.find(" not in {"); at != std::string::npos && message.ends_with("}")) {
    const size_t name_end = message.rfind(": ", at);
    const std::string name = name_end == std::string::npos ? "" : message.substr(0, name_end) + ": ";
    const size_t word = name_end == std::string::npos ? 0 : name_end + 2;
    std::string choices = message.substr(at + 9, message.size() - at - 10);
    for (size_t comma = choices.find(','); comma != std::string::npos; comma = choices.find(',', comma + 2))
      choices.replace(comma, 1, ", ");
    return name + "expected one of " + choices + ", got " + quoted_token(message.substr(word, at - word));
  }
  if (const std::string required = " is required";
      message.ends_with(required) && message.find(' ') == message.size() - required.size())
    return (message.starts_with("-") ? "" : "the ") + message.substr(0, message.size() - required.size()) +
           " is missing (the command's --help says what to give)";
  return message;
}

int run_command_line(CLI::App& app, int argc, char** argv) {
  // Every message is escaped once more here, so that whatever it quotes it stays one harmless line.
  app.failure_message(
      [](const CLI::App*, const CLI::Error& e) { return "gpsurf: " + escaped(in_our_words(e.what())) + "\n"; });
  try {
    std::vector<std::string> args = empty_values_split(app, argc, argv);
    check_words(app, args);
    std::vector<char*> arg_pointers;
    for (std::string& arg : args) arg_pointers.push_back(arg.data());
    app.parse(int(arg_pointers.size()), arg_pointers.data());
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
