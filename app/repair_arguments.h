#pragma once
// The command-line options that repair a mesh as it is read (core/io/mesh_repair.h): --repair and
// --weld, shared by every command that reads a mesh.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "core/io/mesh_io.h"

namespace gps {

struct RepairArguments {
  bool repair = false;
  double weld = -1;  // −1: the default tolerance; a value implies --repair
  /// `options` with these set.
  ImportOptions import_options(ImportOptions options = {}) const;
};

/// Adds --repair and --weld TOLERANCE to `cmd`.
void add_repair_arguments(CLI::App* cmd, RepairArguments& arguments);

/// read_mesh with the repair asked for; when repairing and not `quiet`, a progress bar on a terminal
/// (TerminalProgress) while it works, and the report goes to stdout first
/// ("repair: " and a line per step that changed something, or that nothing needed it), each line
/// naming the file where `name_file` (a command that reads two). What the reader read leniently goes
/// to stderr ("note: " and the note, which names the file).
CovarianceMesh read_mesh_repairing(const std::string& path, const RepairArguments& arguments,
                                   const ImportOptions& options = {}, bool quiet = false, bool name_file = false);

/// Prints the reader's notes to stderr, "note: " before each.
void print_reader_notes(const std::vector<std::string>& notes);

}  // namespace gps
