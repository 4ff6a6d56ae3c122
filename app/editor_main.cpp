// gpsurf-editor: the interactive editor (ui/editor/editor.h); this file only parses the command line.
#include <CLI/CLI.hpp>

#include <iostream>

#include "app/cli_checks.h"
#include "app/crash_stack.h"
#include "app/repair_arguments.h"
#include "app/run_command_line.h"
#include "core/support/error.h"
#include "core/support/freed_memory.h"
#include "core/support/quoted_text.h"
#include "ui/editor/editor.h"
#include "view/camera.h"

int main(int argc, char** argv) {
  gps::report_crash_stack_if_asked("gpsurf-editor");
  gps::keep_freed_memory();
  gps::EditorOptions o;
  std::string size = "1280x800";
  bool no_vsync = false;
  std::string scheme, loop_beta = "loop", up;
  CLI::App app{
      "gpsurf-editor: edit covariance meshes on their GPS limit surface (F1 in the window lists the bindings)"};
  app.add_option("file", o.file, "mesh to open (.ply, .obj, .off, .stl, .gltf, .glb); default: a built-in sample")
      ->check(CLI::ExistingFile);
  app.add_option("--play", o.play, "replay recorded input (EVENTS.json), then exit")->check(CLI::ExistingFile);
  app.add_option("--record", o.record, "record the session's input to EVENTS.json (written on exit)");
  app.add_option("--screenshot", o.screenshot, "after the events, write the window to this PNG and exit");
  auto* save = app.add_option("--save", o.save, "after the events, save the mesh here (.ply) and exit");
  app.add_option("--stats", o.stats, "on exit, write frame time and edit-to-frame time (medians) to this JSON file");
  app.add_option("--size", size, "window size WxH in pixels");
  app.add_flag("--no-vsync", no_vsync, "draw as fast as possible");
  app.add_option("--scheme", scheme, "auto (Loop for a mesh of triangles only), loop or catmull-clark")
      ->check(CLI::IsMember({"auto", "loop", "catmull-clark"}));
  app.add_option("--up", up, "the world axis drawn upward, kept for the file (default: as kept, else y)")
      ->check(CLI::IsMember({"x", "y", "z"}));
  app.add_option("--loop-beta", loop_beta, "Loop vertex weight: Loop's original or Warren's 3/(8n)")
      ->check(CLI::IsMember({"loop", "warren"}));
  gps::RepairArguments repair;  // as gpsurf's commands take them; the weld tolerance also for the repair dialog's
  gps::add_repair_arguments(&app, repair);
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "gpsurf-editor: " + gps::escaped(gps::in_our_words(e.what())) + "\n";
  });
  try {
    app.parse(argc, argv);
    if (save->count() > 0 && o.save.empty()) throw CLI::ValidationError("--save", "give a file to save to, got ''");
    const gps::PixelSize window = gps::parse_pixel_size(size);
    o.width = window.width;
    o.height = window.height;
    o.vsync = !no_vsync;
    if (!scheme.empty()) o.scheme = scheme == "loop" ? 1 : scheme == "catmull-clark" ? 2 : 0;
    o.warren = loop_beta == "warren";
    if (!up.empty()) o.up_axis = gps::up_axis_named(up);
    o.import = repair.import_options();
    return gps::run_editor(o);
  } catch (const CLI::ParseError& e) {
    if (std::string(e.what()).find(": File does not exist: ") != std::string::npos) {  // as gpsurf's commands: 1
      std::cerr << "gpsurf-editor: " << gps::escaped(gps::in_our_words(e.what())) << "\n";
      return 1;
    }
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const gps::Error& e) {
    std::cerr << "gpsurf-editor: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "gpsurf-editor: " << e.what() << "\n";
    return 1;
  }
}
