// gpsurf sample NAME -o FILE: writes a built-in covariance mesh.
#include <iostream>

#include "app/cli_checks.h"
#include "app/commands.h"
#include "core/support/error.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"

namespace gps {

void add_sample_command(CLI::App& app) {
  struct Args {
    std::string name, output;
    int size = 0;
    bool list = false, ascii = false;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("sample", "Write a built-in sample mesh (--list names them)");
  cmd->add_option("name", args->name, "sample name");
  cmd->add_option("-o,--output", args->output, "output file (.ply keeps covariances, .obj positions)");
  cmd->add_option("--size", args->size, "approximate face count for grid and sphere")->transform(integer_in(1, 4000000));
  cmd->add_flag("--list", args->list, "list the samples");
  cmd->add_flag("--ascii", args->ascii, "ASCII PLY (default: binary little endian)");
  cmd->callback([args] {
    if (args->list) {
      for (const auto& name : sample_names()) std::cout << name << "  " << sample_description(name) << "\n";
      return;
    }
    if (args->name.empty()) throw usage_error("sample: give a sample name (see gpsurf sample --list)");
    if (args->output.empty()) throw usage_error("sample: give an output file with -o");
    if (args->size != 0 && !sample_has_size(args->name))
      throw usage_error("sample: --size applies to grid, sphere and icosphere only, not '" + args->name + "'");
    write_mesh(args->output, make_sample(args->name, args->size), !args->ascii);
    std::cout << "wrote " << args->name << " to " << args->output << "\n";
  });
}

}  // namespace gps
