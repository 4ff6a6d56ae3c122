#pragma once
// The commands that need GL or OpenImageIO (bench, render, diff) are a program of their own,
// gpsurf-render, so that gpsurf's other commands start without loading either: gpsurf runs it in
// its own place with the same arguments. Their summaries are here, for both programs' help.
#include <CLI/CLI.hpp>

#include <string_view>

namespace gps {

struct GlCommand {
  const char* name;
  const char* summary;
};

inline constexpr GlCommand kGlCommands[] = {
    {"bench", "Benchmarks (figures for the closing notes; see also build/bench/)"},
    {"render", "Render the limit surface without a display (OSMesa, or EGL with --context)"},
    {"diff", "Difference image of two AOV renders (render --aov), with statistics"},
};

/// The summary of GL command `name` ("" for another name).
inline const char* gl_command_summary(std::string_view name) {
  for (const GlCommand& command : kGlCommands)
    if (name == command.name) return command.summary;
  return "";
}

/// Lists the GL commands in gpsurf's help, with their summaries (their options are gpsurf-render's:
/// `gpsurf render --help`). Nothing in a build without GL.
void add_gl_command_entries(CLI::App& app);

/// Where argv[1] names a GL command, replaces this process by gpsurf-render with the same arguments
/// (found beside this program, or in the folder it is installed to); where that cannot be done it
/// prints one line and exits 1. Returns otherwise.
void run_gl_command_if_named(int argc, char** argv);

}  // namespace gps
