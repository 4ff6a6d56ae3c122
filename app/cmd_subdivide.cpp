// gpsurf subdivide IN -o OUT --levels N: the exact CPU reference GPS subdivision.
#include <iostream>

#include "app/cli_checks.h"
#include "app/commands.h"
#include "app/mesh_output.h"
#include "app/repair_arguments.h"
#include "app/naming_input.h"
#include "core/io/mesh_io.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/plans/planned_surface.h"
#include "core/reference/reference_subdivision.h"

namespace gps {

void add_subdivide_command(CLI::App& app) {
  struct Args {
    std::string input, output, scheme = "auto", beta = "loop";
    int levels = 1;
    bool limit = false, ascii = false;
    RepairArguments repair;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("subdivide", "Gaussian-product subdivision on the CPU (the reference)");
  cmd->add_option("input", args->input, "input mesh")->required();
  cmd->add_option("-o,--output", args->output, "output (.ply keeps covariances and creases, .gltf/.glb covariances, .obj positions and creases)")->required();
  cmd->add_option("--levels", args->levels, "subdivision levels")->transform(integer_in(0, 8));
  cmd->add_option("--scheme", args->scheme,
                  "linear scheme: auto (Loop for a mesh of triangles only, else Catmull-Clark), loop, catmull-clark")
      ->check(CLI::IsMember({"auto", "catmull-clark", "loop"}));
  cmd->add_option("--loop-beta", args->beta, "Loop vertex weight: Loop's original or Warren's 3/(8n)")
      ->check(CLI::IsMember({"loop", "warren"}));
  cmd->add_flag("--limit", args->limit, "move every vertex to its exact limit position");
  cmd->add_flag("--ascii", args->ascii, "ASCII PLY (default: binary little endian)");
  add_repair_arguments(cmd, args->repair);
  cmd->callback([args] {
    const CovarianceMesh m = read_mesh_repairing(args->input, args->repair);
    const PlanOptions named = plan_options_named(args->scheme, args->beta);
    SubdivisionOptions o;
    o.scheme = scheme_for(m.topology(), named);
    o.levels = args->levels;
    o.limit = args->limit;
    o.loop_beta = named.loop_beta;
    const SubdivisionResult r =
        naming_mesh_input(args->input, args->repair.import_options().repair, [&] { return subdivide(m, o); });
    write_mesh_noting(args->output, r.mesh, !args->ascii);
    std::cout << "wrote " << args->output << " (" << (o.scheme == Scheme::loop ? "Loop, " : "Catmull-Clark, ")
              << r.mesh.n_vertices() << " vertices, " << r.mesh.n_faces() << " faces)\n";
  });
}

}  // namespace gps
