// gpsurf tessellate IN -o OUT: the limit surface from the plans, every patch at a uniform level.
#include <iostream>

#include "app/commands.h"
#include "core/dual_map.h"
#include "core/mesh_io.h"
#include "core/plan_builder.h"
#include "core/stencil_table.h"
#include "core/tessellator.h"

namespace gps {

void add_tessellate_command(CLI::App& app) {
  struct Args {
    std::string input, output;
    int depth = 3, level = 8;
    bool binary = false;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("tessellate", "Evaluate the plans on the CPU into a watertight triangle mesh with normals");
  cmd->add_option("input", args->input, "input mesh")->required();
  cmd->add_option("-o,--output", args->output, "output .ply (x y z nx ny nz) or .obj")->required();
  cmd->add_option("--depth", args->depth, "maximum plan depth")->check(CLI::Range(1, 8));
  cmd->add_option("--level", args->level, "tessellation level per patch edge")->check(CLI::Range(1, 64));
  cmd->add_flag("--binary", args->binary, "binary PLY");
  cmd->callback([args] {
    const CovarianceMesh m = read_mesh(args->input);
    const PlanTables tables = build_plans(topology_of(m.mesh), args->depth);
    std::vector<Dual> q(m.n_vertices());
    for (size_t i = 0; i < q.size(); ++i) q[i] = to_dual(m.mean(i), m.covariance(i));
    const TriangleMesh t = tessellate(tables.plans, apply_stencils(tables.stencils, q), args->level);
    write_triangle_mesh(args->output, t, args->binary);
    std::cout << "wrote " << args->output << " (" << tables.plans.n_patches() << " patches, " << t.positions.size()
              << " vertices, " << t.triangles.size() << " triangles)\n";
  });
}

}  // namespace gps
