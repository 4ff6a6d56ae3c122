// gpsurf fit COARSE --target DENSE -o OUT: the coarse covariance mesh's means and covariances moved so
// that its GPS limit surface fits the dense mesh's points (core/fitting/limit_fit.h).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

#include "app/cli_checks.h"
#include "app/commands.h"
#include "app/mesh_output.h"
#include "app/naming_input.h"
#include "app/plan_arguments.h"
#include "app/repair_arguments.h"
#include "app/terminal_progress.h"
#include "core/fitting/face_triangles.h"
#include "core/fitting/fit_progress.h"
#include "core/fitting/limit_fit.h"
#include "core/fitting/surface_distance.h"
#include "core/io/mesh_io.h"

namespace gps {

void add_fit_command(CLI::App& app) {
  struct Args {
    std::string coarse, target, output;
    int iterations = FitOptions().iterations, level = 8;
    std::optional<double> covariance_smoothness;
    double smoothness = 1e-5, covariance_prior = FitOptions().covariance_prior, min_sigma = FitOptions().min_sigma,
           relaxed_min_sigma = FitOptions().relaxed_min_sigma, max_sigma = FitOptions().max_sigma,
           tolerance = FitOptions().tolerance, time = INFINITY, normal_weight = FitOptions().normal_weight;
    bool plain = false, ascii = false, quiet = false;
    PlanArguments plans;
    RepairArguments repair;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand(
      "fit",
      "Fit a coarse covariance mesh's limit surface to a dense mesh's vertices (or a point cloud's points): "
      "Levenberg-Marquardt on the squared distances to their closest limit points, moving means and "
      "covariances; then report the distances as compare does");
  cmd->add_option("coarse", args->coarse, "covariance mesh to fit (its Gaussians are the start)")->required();
  cmd->add_option("-t,--target", args->target, "mesh or point-cloud PLY whose vertices the surface is fitted to")
      ->required();
  cmd->add_option("-o,--output", args->output, "output covariance PLY")->required();
  cmd->add_option(
         "--iterations", args->iterations,
         "the most Levenberg-Marquardt iterations (default 100; the fit stops sooner once converged, --tolerance)")
      ->transform(integer_in(0, 1000));
  cmd->add_option(
         "--tolerance", args->tolerance,
         "stop when an iteration lowers the rms distance by less than this fraction of it (default 0.01; 0: never)")
      ->check(number_in(0, 1));
  cmd->add_option("--time", args->time, "stop after the iteration that passes this many seconds (default: never)")
      ->check(positive_number(1e9));
  cmd->add_flag("--plain", args->plain,
                "fit the means only, every covariance the same isotropic one (ordinary subdivision-surface fitting)");
  cmd->add_option("--smoothness", args->smoothness,
                  "weight of the smoothness term against the mean squared distance (default 1e-5)")
      ->check(number_in(0, 1e6));
  cmd->add_option("--covariance-smoothness", args->covariance_smoothness,
                  "weight of the smoothness term on the covariances (the Laplacian of their changes) against the mean "
                  "squared distance (default 0)")
      ->check(number_in(0, 1e6));
  cmd->add_option("--covariance-prior", args->covariance_prior,
                  "weight of the prior that keeps each covariance near its start, against the mean squared distance "
                  "(default 0: none)")
      ->check(number_in(0, 1e6));
  cmd->add_option("--normal-weight", args->normal_weight,
                  "weight of the term that turns the surface's normals toward those of the target's faces, against "
                  "the squared distance (default 0.001; 0: none; a point cloud has no normals; ignored by --plain)")
      ->check(number_in(0, 1e6));
  cmd->add_option(
         "--min-sigma", args->min_sigma,
         "least standard deviation of each Gaussian, over the mean length of its vertex's edges (default 0.35)")
      ->check(number_in(0, 1e6));
  cmd->add_option("--relaxed-min-sigma", args->relaxed_min_sigma,
                  "least standard deviation once the fit has converged at --min-sigma, over the same length: the fit "
                  "goes on at this bound until it converges again (default 0.1; at or above --min-sigma: no second "
                  "stage)")
      ->check(number_in(0, 1e6));
  cmd->add_option(
         "--max-sigma", args->max_sigma,
         "greatest standard deviation of each Gaussian, over the mean length of its vertex's edges (default 1)")
      ->check(number_in(1e-6, 1e6));
  auto* level = cmd->add_option("--level", args->level,
                                "tessellation level of the limit surface the final report measures (0: no report; "
                                "default 8, lower where that would make more than 2 million triangles)")
                    ->transform(integer_in(0, 64));
  cmd->add_flag("--ascii", args->ascii, "ASCII PLY (default: binary little endian)");
  cmd->add_flag("-q,--quiet", args->quiet, "print only errors (no iterations, no report, no progress bar)");
  add_plan_arguments(cmd, args->plans);
  add_repair_arguments(cmd, args->repair);
  cmd->callback([args, level] {
    if (!(args->min_sigma < args->max_sigma)) {
      std::ostringstream said;
      said << "--min-sigma " << args->min_sigma << " must be below --max-sigma " << args->max_sigma
           << " (defaults 0.35 and 1)";
      throw usage_error(said.str());
    }
    check_mesh_output(args->output);  // before the fit, which may take minutes
    const CovarianceMesh coarse = read_mesh_repairing(args->coarse, args->repair, {}, args->quiet, true);
    // The target's points whatever its faces (a scan that is not a manifold), with the normals of the
    // faces around them (none for a point cloud).
    PolygonSoup target;
    target.positions = read_points(args->target, &target.faces);
    const std::vector<Vec3>& targets = target.positions;
    const std::vector<Vec3> normals = smooth_vertex_normals(face_triangles(target));
    FitOptions options;
    options.iterations = args->iterations;
    options.plain = args->plain;
    options.smoothness = args->smoothness;
    options.covariance_smoothness = args->covariance_smoothness;
    options.covariance_prior = args->covariance_prior;
    options.normal_weight = args->normal_weight;
    options.min_sigma = args->min_sigma;
    options.relaxed_min_sigma = args->relaxed_min_sigma;
    options.max_sigma = args->max_sigma;
    options.tolerance = args->tolerance;
    options.time_budget = args->time;
    options.plans = args->plans.options();
    // The bar (core/fitting/fit_progress.h) gives way to each iteration's line.
    TerminalProgress bar("fitting", args->quiet);
    FitProgress done(options);
    bool relaxed_shown = false;
    options.progress = [&](const FitIteration& it) {
      if (args->quiet) return;
      bar.clear();
      if (it.relaxed && !relaxed_shown) {
        std::printf("the standard deviations' lower bound relaxed from %g to %g of their vertex's mean edge length\n",
                    options.min_sigma, options.relaxed_min_sigma);
        relaxed_shown = true;
      }
      std::printf("iteration %d: rms %.3e, max %.3e (of the diagonal), %.2f s\n", it.iteration, it.error.relative_rms(),
                  it.error.relative_max(), it.seconds);
      std::fflush(stdout);
      bar.update(done.after(it));
    };
    if (!args->quiet)
      std::cout << "fitting " << coarse.n_vertices() << " vertices" << (args->plain ? " (plain)" : "") << " to "
                << targets.size() << " points\n"
                << std::flush;
    const FitResult result =
        naming_input(args->coarse, [&] { return fit_limit_surface(coarse, targets, options, normals); });
    bar.finish();
    if (!args->quiet)
      std::cout << "stopped after " << result.iterations.size() - 1 << " iterations: " << describe(result.stop) << "\n";
    write_mesh_noting(args->output, result.mesh, !args->ascii, args->quiet);
    if (args->quiet) return;
    std::cout << "wrote " << args->output << "\n";
    if (args->level == 0) return;
    const LimitTriangles limit = naming_input(args->output, [&] {
      return limit_surface_triangles(result.mesh, args->level, options.plans,
                                     level->count() > 0 ? INFINITY : kMeasuredTriangles);
    });
    std::cout << "target points to the fitted limit surface (level " << limit.level << "):\n"
              << describe(distances_to_surface(targets, limit.triangles));
  });
}

}  // namespace gps
