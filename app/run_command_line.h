#pragma once
// What both gpsurf programs do with their command line: parse it, run the subcommand, and turn
// every error into one line on stderr and an exit code (2 for usage, 1 otherwise).
#include <CLI/CLI.hpp>

namespace gps {

/// Parses argv with `app` (its subcommands run from their callbacks) and returns the exit code;
/// every message begins "gpsurf: ".
int run_command_line(CLI::App& app, int argc, char** argv);

/// CLI11's message in our words where it has its own wording ("--level excludes --pixels": "--level
/// and --pixels exclude each other; give one of them"), else as it is.
std::string in_our_words(const std::string& message);

}  // namespace gps
