// gpsurf tessellate IN -o OUT: the limit surface from the plans, every patch at a uniform level.
#include <iostream>

#include "app/cli_checks.h"
#include "app/commands.h"
#include "app/repair_arguments.h"
#include "app/naming_input.h"
#include "app/plan_arguments.h"
#include "app/terminal_progress.h"
#include "core/evaluation/surface_samples.h"
#include "core/io/mesh_io.h"
#include "core/plans/planned_surface.h"
#include "core/evaluation/tessellator.h"

namespace gps {

void add_tessellate_command(CLI::App& app) {
  struct Args {
    std::string input, output;
    int level = 8;
    PlanArguments plans;
    bool ascii = false, quiet = false;
    RepairArguments repair;
  };
  auto args = std::make_shared<Args>();
  auto* cmd =
      app.add_subcommand("tessellate", "Evaluate the plans on the CPU into a watertight triangle mesh with normals");
  cmd->add_option("input", args->input, "input mesh")->required();
  cmd->add_option("-o,--output", args->output, "output .ply (x y z nx ny nz), .obj, .gltf or .glb")->required();
  add_plan_arguments(cmd, args->plans);
  cmd->add_option("--level", args->level, "tessellation level per patch edge")->transform(integer_in(1, 64));
  cmd->add_flag("--ascii", args->ascii, "ASCII PLY (default: binary little endian)");
  cmd->add_flag("-q,--quiet", args->quiet, "print only errors (no summary, no progress bar)");
  add_repair_arguments(cmd, args->repair);
  cmd->callback([args] {
    const CovarianceMesh m = read_mesh_repairing(args->input, args->repair, {}, args->quiet);
    const PlannedSurface surface = naming_mesh_input(args->input, args->repair.import_options().repair,
                                                     [&] { return PlannedSurface(m, args->plans.options()); });
    TerminalProgress bar("tessellating", args->quiet);
    const TriangleMesh t = naming_input(args->input, [&] { return tessellate(surface, args->level, bar.report()); });
    bar.finish();
    write_triangle_mesh(args->output, t, !args->ascii);
    if (args->quiet) return;
    std::cout << "wrote " << args->output << " (" << (surface.scheme() == Scheme::loop ? "Loop, " : "Catmull-Clark, ")
              << surface.tables().plans.n_patches() << " patches, " << t.positions.size() << " vertices, "
              << t.triangles.size() << " triangles)\n";
  });
}

}  // namespace gps
