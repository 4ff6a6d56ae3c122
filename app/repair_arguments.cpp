#include "app/repair_arguments.h"

#include <iostream>

#include "app/cli_checks.h"
#include "app/terminal_progress.h"
#include "core/support/quoted_text.h"

namespace gps {

ImportOptions RepairArguments::import_options(ImportOptions options) const {
  options.repair = repair || weld >= 0;
  if (weld >= 0) options.weld_tolerance = weld;
  return options;
}

void add_repair_arguments(CLI::App* cmd, RepairArguments& arguments) {
  cmd->add_flag("--repair", arguments.repair,
                "repair the mesh as read: weld, drop degenerate/duplicate faces, separate fins and pinch "
                "vertices, orient, drop isolated vertices (the report is printed first)");
  cmd->add_option("--weld", arguments.weld,
                  "weld tolerance as a fraction of the bounding-box diagonal (default 1e-6); implies --repair")
      ->check(non_negative_number());
}

CovarianceMesh read_mesh_repairing(const std::string& path, const RepairArguments& arguments,
                                   const ImportOptions& options, bool quiet, bool name_file) {
  ImportOptions o = arguments.import_options(options);
  TerminalProgress bar("repairing", quiet || !o.repair);
  o.repair_progress = bar.report();
  RepairReport report;
  std::vector<std::string> notes;
  CovarianceMesh mesh = read_mesh(path, o, &report, &notes);
  bar.finish();
  if (!quiet) print_reader_notes(notes);  // --quiet prints only errors
  if (o.repair && !quiet) {
    const std::string prefix = "repair: " + (name_file ? escaped(path) + ": " : std::string());
    const auto lines = report.lines();
    if (lines.empty()) std::cout << prefix << "nothing to repair\n";
    for (const std::string& line : lines) std::cout << prefix << line << "\n";
  }
  return mesh;
}

void print_reader_notes(const std::vector<std::string>& notes) {
  for (const std::string& note : notes) std::cerr << "note: " << note << "\n";
}

}  // namespace gps
