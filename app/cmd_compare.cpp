// gpsurf compare A B: how far A's points lie from B's GPS limit surface, and how far their normals turn from
// its normals there (core/fitting/surface_distance.h).
#include <iostream>

#include "app/cli_checks.h"
#include "app/commands.h"
#include "app/naming_input.h"
#include "app/plan_arguments.h"
#include "app/repair_arguments.h"
#include "core/fitting/face_triangles.h"
#include "core/fitting/surface_distance.h"
#include "core/io/mesh_io.h"

namespace gps {

void add_compare_command(CLI::App& app) {
  struct Args {
    std::string first, second;
    int level = 8;
    bool both = false, samples = false, linear = false;
    PlanArguments plans;
    RepairArguments repair;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand(
      "compare",
      "Distances from A's vertices to B's limit surface (tessellated densely): rms, 99th percentile and max, each also "
      "over A's bounding-box diagonal; and the rms angle between A's normals (of its faces, where they meet at no "
      "sharp edge or corner) and the surface's");
  cmd->add_option("A", args->first, "mesh whose points are measured (its vertices: any mesh file, manifold or not)")
      ->required();
  cmd->add_option("B", args->second, "mesh whose limit surface they are measured to")->required();
  cmd->add_flag("--both", args->both, "also B's points to A's limit surface");
  auto* samples =
      cmd->add_flag("--samples", args->samples,
                    "measure the points of the measured mesh's limit surface at --level instead of its vertices");
  cmd->add_flag("--linear", args->linear,
                "measure to the faces themselves (the piecewise-linear control mesh) instead of the limit surface")
      ->excludes(samples);
  auto* level = cmd->add_option("--level", args->level,
                                "tessellation level of the limit surfaces (default 8, lower for a surface that would "
                                "make more than 2 million triangles)")
                    ->transform(integer_in(1, 64));
  add_plan_arguments(cmd, args->plans);
  add_repair_arguments(cmd, args->repair);
  cmd->callback([args, level] {
    const PlanOptions options = args->plans.options();
    // A's surface is needed only by --both and --samples; else its vertices are read as points, whatever
    // its faces (a scan that is not a manifold, a point cloud), and --repair mends B alone.
    const bool a_surface = args->both || args->samples;
    const CovarianceMesh a =
        a_surface ? read_mesh_repairing(args->first, args->repair, {}, false, true) : CovarianceMesh();
    // A's points as read, with the normals of the faces around them (none for a point cloud).
    PolygonSoup a_soup;
    if (!a_surface) a_soup.positions = read_points(args->first, &a_soup.faces);
    const CovarianceMesh b = read_mesh_repairing(args->second, args->repair, {}, false, true);
    const double max_triangles = level->count() > 0 ? INFINITY : kMeasuredTriangles;
    const auto limit_of = [&](const std::string& path, const CovarianceMesh& m) {
      if (args->linear) return LimitTriangles{face_triangles(m), 0};
      return naming_mesh_input(path, args->repair.import_options().repair,
                               [&] { return limit_surface_triangles(m, args->level, options, max_triangles); });
    };
    const LimitTriangles limit_b = limit_of(args->second, b);
    LimitTriangles limit_a;
    if (a_surface) limit_a = limit_of(args->first, a);
    // The points measured, with their normals: a mesh's limit samples (--samples) or its vertices.
    // A vertex on a sharp edge or corner has no one normal (its faces' average is neither side's):
    // it is left out of the angles (core/fitting/face_triangles.h).
    const auto with_smooth_normals = [](TriangleMesh points) {
      points.normals = smooth_vertex_normals(points);
      return points;
    };
    const auto points_of = [&](const CovarianceMesh& m, const LimitTriangles& own_limit) {
      return with_smooth_normals(args->samples ? own_limit.triangles : face_triangles(m));
    };
    const auto report = [&](const std::string& from, const TriangleMesh& points, const std::string& to,
                            const LimitTriangles& limit) {
      std::cout << escaped(from) << " (" << points.positions.size() << (args->samples ? " limit samples" : " vertices")
                << ") to " << (args->linear ? "the faces of " : "the limit surface of ") << escaped(to);
      if (!args->linear) std::cout << " (level " << limit.level << ")";
      const SurfaceDistance surface(limit.triangles);
      const double diagonal = bounding_box_diagonal(points.positions);
      std::cout << ":\n"
                << describe(summarise_distances(surface.distances(points.positions), diagonal))
                << describe(summarise_angles(surface.normal_angles(points.positions, points.normals),
                                             points.positions.size()));
    };
    report(args->first, a_surface ? points_of(a, limit_a) : with_smooth_normals(face_triangles(a_soup)), args->second,
           limit_b);
    if (args->both) report(args->second, points_of(b, limit_b), args->first, limit_a);
  });
}

}  // namespace gps
