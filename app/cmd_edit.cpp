// gpsurf edit IN -o OUT --ops OPS: modelling operations (core/modelling/operation_list.h) applied in
// order, for scripts and regression tests; a refused operation writes nothing.
#include <filesystem>
#include <iostream>

#include "app/commands.h"
#include "app/mesh_output.h"
#include "app/repair_arguments.h"
#include "core/io/mesh_io.h"
#include "core/support/quoted_text.h"
#include "core/io/text_file.h"
#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "core/modelling/operation_list.h"

namespace gps {

void add_edit_command(CLI::App& app) {
  struct Args {
    std::string input, output, ops;
    bool ascii = false, quiet = false;
    RepairArguments repair;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("edit", "Apply modelling operations (extrude, loop cut, merge, ...) to a mesh");
  cmd->add_option("input", args->input, "input mesh, or sample:NAME for a built-in one")->required();
  cmd->add_option("-o,--output", args->output, "output (.ply keeps covariances, .obj positions)")->required();
  cmd->add_option("--ops", args->ops,
                  "the operations: a JSON array such as '[{\"op\":\"loop_cut\",\"edge\":[0,1]}]', or @FILE.json")
      ->required();
  cmd->add_flag("--ascii", args->ascii, "ASCII PLY (default: binary little endian)");
  cmd->add_flag("-q,--quiet", args->quiet, "print only errors");
  add_repair_arguments(cmd, args->repair);
  cmd->callback([args] {
    const bool from_file = !args->ops.empty() && args->ops[0] == '@';
    const std::string source = from_file ? args->ops.substr(1) : std::string();  // inline: named by ops[i] alone
    // A file name given without its @ would be read as JSON: say how to read the file instead.
    if (const size_t first = args->ops.find_first_not_of(" \t\r\n");
        !from_file && first != std::string::npos && args->ops[first] != '[' && std::filesystem::exists(args->ops))
      throw usage_error("--ops " + quoted_token(args->ops) +
                        " is not a JSON array; to read the operations from that file, write --ops @" + args->ops);
    const OperationList ops = [&] {
      try {
        if (!from_file) return OperationList::parse(args->ops, source);
        std::string text;
        try {
          text = read_text_file(source);
        } catch (const Error& e) {  // named by its option, as the mesh's file is by its own message
          throw Error("--ops: " + std::string(e.what()), e.kind());
        }
        return OperationList::parse(text, source);
      } catch (const Error& e) {
        // Inline text that is not JSON at all is named by its option.
        if (!from_file && std::string_view(e.what()).starts_with("not valid JSON"))
          throw usage_error("--ops: " + std::string(e.what()));
        throw;
      }
    }();
    const CovarianceMesh mesh = args->input.rfind("sample:", 0) == 0
                                    ? make_sample(args->input.substr(7))
                                    : read_mesh_repairing(args->input, args->repair, {}, args->quiet);
    std::vector<std::string> summaries;
    const Modelled result = [&] {
      try {
        return ops.apply(mesh, &summaries);
      } catch (const Error& e) {
        throw Error(escaped(args->input) + ": " + e.what(), e.kind());
      }
    }();
    write_mesh_noting(args->output, result.mesh, !args->ascii, args->quiet);
    if (args->quiet) return;
    for (size_t i = 0; i < summaries.size(); ++i) std::cout << "ops[" << i << "]: " << summaries[i] << "\n";
    std::cout << "wrote " << args->output << " (" << result.mesh.n_vertices() << " vertices, " << result.mesh.n_faces()
              << " faces)\n";
  });
}

}  // namespace gps
