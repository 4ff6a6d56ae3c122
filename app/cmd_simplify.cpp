// gpsurf simplify IN -o OUT: a dense triangle mesh decimated into a coarse covariance mesh whose
// Gaussians come from the input regions collapsed into each vertex (core/fitting/mesh_simplification.h).
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>

#include "app/cli_checks.h"
#include "app/commands.h"
#include "app/mesh_output.h"
#include "core/support/quoted_text.h"
#include "app/naming_input.h"
#include "app/repair_arguments.h"
#include "app/terminal_progress.h"
#include "core/fitting/limit_placement.h"
#include "core/fitting/mesh_simplification.h"
#include "core/fitting/surface_distance.h"
#include "core/io/mesh_io.h"

namespace gps {

void add_simplify_command(CLI::App& app) {
  struct Args {
    std::string input, output;
    size_t vertices = 0;
    double ratio = 0, bias = 0.05, max_normal_deviation = 45, error = 0;
    int level = 8;
    bool ascii = false, quiet = false, quads = false, limit = false;
    RepairArguments repair;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand(
      "simplify",
      "Decimate a triangle mesh (faces of more sides are fanned into triangles first) by edge collapses that keep "
      "its topology and creases, each coarse vertex carrying the Gaussian of the input region collapsed into it; "
      "then report the distances of the input's vertices to the result's limit surface");
  cmd->add_option("input", args->input, "input mesh (its covariances, if any, are not used)")->required();
  cmd->add_option("-o,--output", args->output, "output covariance PLY")->required();
  auto* vertices = cmd->add_option("--vertices", args->vertices, "vertices to keep (at least 4)")
                       ->transform(integer_in(4, 1LL << 40));
  auto* ratio = cmd->add_option("--ratio", args->ratio, "fraction of the input's vertices to keep, in (0, 1]")
                    ->check(positive_number(1));
  vertices->excludes(ratio);
  auto* error = cmd->add_option("--error", args->error,
                                "stop short of a collapse that would move the surface further than this, over the "
                                "input's bounding-box diagonal (the rms distance of the merged region's face planes)")
                    ->check(positive_number(1));
  cmd->add_option("--bias", args->bias, "thickness of the input's faces across their planes (as Eq. 16's bias)")
      ->check(positive_number());
  cmd->add_option("--max-normal-deviation", args->max_normal_deviation,
                  "the most, in degrees, a collapse may turn a face's normal")
      ->check(number_in(1, 90));
  auto* level = cmd->add_option("--level", args->level,
                                "tessellation level of the limit surface the report measures (0: no report; default 8, "
                                "lower where that would make more than 2 million triangles)")
                    ->transform(integer_in(0, 64));
  cmd->add_flag("--quads", args->quads,
                "pair the result's triangles into quads where they make nearly square, flat ones (a quad-dominant mesh "
                "for Catmull-Clark modelling)");
  cmd->add_flag("--limit", args->limit,
                "move each vertex out by how far its limit position falls short of it, so that the limit surface "
                "lies near the positions kept, on the input, and not inside the triangles wherever they curve");
  cmd->add_flag("--ascii", args->ascii, "ASCII PLY (default: binary little endian)");
  cmd->add_flag("-q,--quiet", args->quiet, "print only errors (no report, no progress bar)");
  add_repair_arguments(cmd, args->repair);
  cmd->callback([args, vertices, ratio, error, level] {
    if (vertices->count() == 0 && ratio->count() == 0 && error->count() == 0)
      throw usage_error("simplify: give --vertices N, --ratio R or --error E");
    // Simplifying uses the input's faces only: no covariances inferred for it.
    ImportOptions import;
    import.covariance = ImportOptions::Covariance::isotropic;
    const CovarianceMesh input = read_mesh_repairing(args->input, args->repair, import, args->quiet);
    SimplifyOptions options;
    options.bias = args->bias;
    options.max_normal_deviation_degrees = args->max_normal_deviation;
    options.max_error = args->error;
    options.quads = args->quads;
    // --error alone: as few vertices as the error allows.
    options.target_vertices = vertices->count() > 0 ? args->vertices
                              : ratio->count() > 0  ? size_t(std::llround(args->ratio * double(input.n_vertices())))
                                                    : 4;
    if (options.target_vertices < 4)
      throw usage_error(escaped(args->input) + ": --ratio " + quoted_token(ratio->as<std::string>()) +
                        " keeps fewer than 4 of its " + std::to_string(input.n_vertices()) + " vertices");
    TerminalProgress progress("simplifying", args->quiet);
    options.progress = progress.report();
    SimplifiedMesh s = naming_mesh_input(args->input, args->repair.import_options().repair,
                                         [&] { return simplify_mesh(input, options); });
    progress.finish();
    std::optional<LimitPlacement> placed;
    if (args->limit) {
      placed = naming_input(args->input, [&] { return place_for_limit(s.mesh, PlanOptions{}); });
      s.mesh = std::move(placed->mesh);
    }
    write_mesh_noting(args->output, s.mesh, !args->ascii, args->quiet);
    if (args->quiet) return;
    if (s.triangulated) std::cout << "fanned the faces of more than 3 sides into triangles\n";
    std::cout << "simplified " << s.input_vertices << " vertices, " << s.input_triangles << " triangles to "
              << s.mesh.n_vertices() << " vertices, " << s.mesh.n_faces() + s.quads
              << " triangles";  // before --quads joined pairs of them
    // What held the collapses back, the normals' bound by its option (its default too: 45°).
    const auto kept = [&] {
      std::ostringstream said;
      said << "the topology, manifoldness, face orientations and faces' normals within " << args->max_normal_deviation
           << "° (--max-normal-deviation)";
      return said.str();
    };
    if (error->count() > 0 && s.mesh.n_vertices() > options.target_vertices)
      std::cout << " (no further collapse keeps within --error " << args->error << ", " << kept() << ")";
    else if (s.mesh.n_vertices() > options.target_vertices)
      std::cout << " (asked " << options.target_vertices << ": no further collapse keeps " << kept() << ")";
    if (args->quads)
      std::cout << ", " << s.quads << " pairs of them joined into quads (" << s.mesh.n_faces() << " faces)";
    if (placed)
      std::cout << "\nmoved the vertices out for the limit surface: its rms distance from the positions kept, "
                << placed->gap_before << " → " << placed->gap_after << " of the diagonal";
    std::cout << "\nwrote " << args->output << "\n";
    if (args->level == 0) return;
    const LimitTriangles limit = naming_input(args->output, [&] {
      return limit_surface_triangles(s.mesh, args->level, {}, level->count() > 0 ? INFINITY : kMeasuredTriangles);
    });
    std::cout << "input vertices to the simplified limit surface (level " << limit.level << "):\n"
              << describe(distances_to_surface(vertex_means(input), limit.triangles));
  });
}

}  // namespace gps
