// gpsurf.fit, distance and compare: a limit surface fitted to points, and distances from points to
// a limit surface (or to a mesh's faces).
#include <pybind11/stl.h>

#include <cmath>
#include <optional>

#include "core/evaluation/surface_samples.h"
#include "core/evaluation/tessellation_size.h"
#include "core/evaluation/tessellator.h"
#include "core/fitting/face_triangles.h"
#include "core/fitting/fit_progress.h"
#include "core/fitting/limit_fit.h"
#include "core/fitting/surface_distance.h"
#include "python/arrays.h"
#include "python/background_call.h"
#include "python/bindings.h"
#include "python/handles.h"

namespace gps::python {
namespace {

// The points of a Mesh (its vertices) or of an (n, 3) array.
std::vector<Vec3> points_of(const py::object& points, const char* what) {
  if (py::isinstance<MeshHandle>(points)) return vertex_means(*points.cast<const MeshHandle&>().mesh);
  const DoubleArray array = contiguous<double>(points);
  if (!array) throw py::type_error(std::string(what) + ": expected a Mesh or an (n, 3) array of points");
  return array_to_rows(array, what);
}

// What a measurement gives: every point's distance and, for each point with a normal, the angle
// between it and the surface's normal at the nearest point (degrees, as lines).
struct Measured {
  std::vector<double> distances, normal_angles;
};

// Distances from points to a Surface's kept plans, a Mesh's limit surface, or (linear) its faces.
struct Measurement {
  std::vector<Vec3> points;
  std::shared_ptr<const CovarianceMesh> points_mesh;  // the Mesh whose vertices are the points, if one
  std::shared_ptr<const PlannedSurface> plans;        // empty for a Mesh
  std::shared_ptr<const CovarianceMesh> mesh;
  int level = 8;
  bool level_given = false, linear = false;

  // The triangles measured to: the faces where `linear`, else the limit surface at `level`, or
  // lower where an unasked level would make more than kMeasuredTriangles.
  TriangleMesh triangles() const {
    if (linear) return face_triangles(*mesh);
    const double max_triangles = level_given ? INFINITY : kMeasuredTriangles;
    if (!plans) return limit_surface_triangles(*mesh, level, PlanOptions{}, max_triangles).triangles;
    const PatchPlans& p = plans->tables().plans;
    int used = level;
    while (used > 1 && tessellation_size(p, used).faces > max_triangles) --used;
    return tessellate(*plans, used);
  }

  // The distance of every point (and, with `angles`, the normals' angles), a chunk at a time so
  // that a stop is seen between chunks.
  Measured measure(CallControl& control, bool angles) const {
    constexpr size_t kChunk = 1 << 16;
    const TriangleMesh surface = triangles();
    const SurfaceDistance measure(surface);
    // A Mesh's points have its faces' area-weighted normals, but none on a sharp edge or corner
    // (gpsurf compare's); an array's have none.
    const std::vector<Vec3> normals =
        angles && points_mesh ? smooth_vertex_normals(face_triangles(*points_mesh)) : std::vector<Vec3>();
    Measured out;
    out.distances.reserve(points.size());
    const auto chunk_of = [](const std::vector<Vec3>& all, size_t first) {
      return std::vector<Vec3>(all.begin() + ptrdiff_t(first),
                               all.begin() + ptrdiff_t(std::min(all.size(), first + kChunk)));
    };
    for (size_t first = 0; first < points.size(); first += kChunk) {
      control.throw_if_stopped();
      control.report(double(first) / double(points.size()));
      const std::vector<Vec3> chunk = chunk_of(points, first);
      const std::vector<double> d = measure.distances(chunk);
      out.distances.insert(out.distances.end(), d.begin(), d.end());
      if (normals.empty()) continue;
      const std::vector<double> a = measure.normal_angles(chunk, chunk_of(normals, first));
      out.normal_angles.insert(out.normal_angles.end(), a.begin(), a.end());
    }
    return out;
  }
};

// The arguments of distance() and compare(), checked (`what`: the points' parameter name).
Measurement measurement(const py::object& points, const py::object& to, const std::optional<Integer>& level,
                        bool linear, const char* what) {
  Measurement m;
  m.points = points_of(points, what);
  if (py::isinstance<MeshHandle>(points)) m.points_mesh = points.cast<const MeshHandle&>().mesh;
  if (py::isinstance<SurfaceHandle>(to)) {
    const auto& s = to.cast<const SurfaceHandle&>();
    m.plans = s.surface, m.mesh = s.mesh;
  } else if (py::isinstance<MeshHandle>(to)) {
    m.mesh = to.cast<const MeshHandle&>().mesh;
  } else {
    throw py::type_error("expected a gpsurf.Mesh or gpsurf.Surface to measure to");
  }
  m.level = level ? int_in(*level, 1, 64, "level") : 8;
  m.level_given = level.has_value();
  m.linear = linear;
  return m;
}

// The Python name of a stop reason.
const char* fit_stop_name(FitStop stop) {
  switch (stop) {
    case FitStop::iterations:
      return "iterations";
    case FitStop::converged:
      return "converged";
    case FitStop::time:
      return "time";
    case FitStop::no_descent:
      return "no_descent";
  }
  return "";
}

}  // namespace

void add_fitting_bindings(py::module_& m) {
  m.def(
      "fit",
      [](const MeshHandle& coarse, const py::object& target, const Integer& iterations, bool plain, double smoothness,
         double tolerance, std::optional<double> time, const py::object& progress, bool report,
         std::optional<double> covariance_smoothness, double covariance_prior, double min_sigma, double max_sigma,
         double normal_weight, double relaxed_min_sigma) -> py::object {
        FitOptions o;
        o.iterations = int_in(iterations, 0, 1000, "iterations");
        o.plain = plain;
        o.smoothness = number_in(smoothness, 0, 1e6, "smoothness");
        if (covariance_smoothness)
          o.covariance_smoothness = number_in(*covariance_smoothness, 0, 1e6, "covariance_smoothness");
        o.covariance_prior = number_in(covariance_prior, 0, 1e6, "covariance_prior");
        o.normal_weight = number_in(normal_weight, 0, 1e6, "normal_weight");
        // The bounds as gpsurf fit --min-sigma --max-sigma take them: the lower below the upper.
        o.min_sigma = number_in(min_sigma, 0, 1e6, "min_sigma");
        o.max_sigma = positive_number(max_sigma, "max_sigma");
        if (!(o.min_sigma < o.max_sigma))
          throw py::value_error("min_sigma: expected below max_sigma (" + shown_number(max_sigma) + "), got " +
                                shown_number(min_sigma));
        o.relaxed_min_sigma = number_in(relaxed_min_sigma, 0, 1e6, "relaxed_min_sigma");
        if (!(tolerance >= 0 && tolerance <= 1)) throw py::value_error("tolerance: expected a fraction 0..1");
        o.tolerance = tolerance;
        if (time && !(std::isfinite(*time) && *time > 0))
          throw py::value_error("time: expected a finite number of seconds above 0, or None");
        o.time_budget = time.value_or(INFINITY);
        std::vector<Vec3> targets = points_of(target, "target");
        if (targets.empty()) throw py::value_error("target: has no points to fit to");
        // A Mesh's normals as gpsurf fit takes them from its target's faces; an array has none.
        std::shared_ptr<const CovarianceMesh> target_mesh;
        if (py::isinstance<MeshHandle>(target)) target_mesh = target.cast<const MeshHandle&>().mesh;
        FitResult result = call_in_background(
            [source = coarse.mesh, targets = std::move(targets), target_mesh, o](CallControl& control) mutable {
              o.progress = [&control, done = FitProgress(o)](const FitIteration& it) mutable {
                control.throw_if_stopped();
                control.report(done.after(it));
              };
              const std::vector<Vec3> normals =
                  target_mesh ? smooth_vertex_normals(face_triangles(*target_mesh)) : std::vector<Vec3>();
              FitResult fitted = fit_limit_surface(*source, targets, o, normals);
              // Targets near the positions' limit can draw the control points past it: refused as a Mesh would be.
              validate_gaussians(fitted.mesh, "the fitted mesh");
              return fitted;
            },
            progress, false);
        py::object mesh = py::cast(hold(std::move(result.mesh)));
        if (!report) return mesh;
        std::vector<double> rms;
        for (const FitIteration& it : result.iterations) rms.push_back(it.error.relative_rms());
        py::dict details;
        details["stop"] = fit_stop_name(result.stop);
        details["reason"] = describe(result.stop);
        details["iterations"] = int(result.iterations.size()) - 1;
        details["relative_rms"] = rms;
        return py::make_tuple(mesh, details);
      },
      py::arg("coarse"), py::arg("target"), py::arg("iterations") = FitOptions().iterations, py::arg("plain") = false,
      py::arg("smoothness") = 1e-5, py::arg("tolerance") = FitOptions().tolerance, py::arg("time") = py::none(),
      py::arg("progress") = py::none(), py::arg("report") = false, py::kw_only(),
      py::arg("covariance_smoothness") = py::none(), py::arg("covariance_prior") = FitOptions().covariance_prior,
      py::arg("min_sigma") = FitOptions().min_sigma, py::arg("max_sigma") = FitOptions().max_sigma,
      py::arg("normal_weight") = FitOptions().normal_weight,
      py::arg("relaxed_min_sigma") = FitOptions().relaxed_min_sigma,
      "The limit surface of `coarse` fitted to `target` (a Mesh's vertices or an (n, 3) array of points), as gpsurf "
      "fit fits it: up to `iterations` (0..1000) Levenberg-Marquardt steps on the squared distances from the points "
      "to their closest limit points, moving the means and (unless plain) the covariances; smoothness: the weight "
      "of the smoothness term on the means (0..1e6). Of the covariances (ignored when plain): "
      "covariance_smoothness, the weight of the smoothness term on their changes (0..1e6; None: 0 for a Mesh "
      "target, whose normals keep the surface smooth, 1e-4 for an array); covariance_prior, the "
      "weight of the prior that keeps each near its start (0..1e6, 0: none); min_sigma and max_sigma, the least "
      "and greatest standard deviation of each Gaussian over the mean length of its vertex's edges (min_sigma "
      "0..1e6, max_sigma finite and above it); relaxed_min_sigma, the lower bound once the fit has converged at "
      "min_sigma, where it goes on until it converges again (0..1e6; at or above min_sigma: no second stage); "
      "normal_weight, the weight of the term that turns the surface's "
      "normals toward those of a Mesh target's faces (0..1e6, 0: none; an array has no normals). tolerance: stop "
      "when an iteration lowers both the rms distance and the fit's objective by less than this fraction (0: "
      "never); time: stop after the iteration that passes this many seconds (None: "
      "never). progress: called with the fraction of iterations done; returning False cancels (gpsurf.Cancelled). "
      "Returns the fitted Mesh; report=True: (Mesh, dict) with stop ('iterations', 'converged', 'time' or "
      "'no_descent'), reason (in words), iterations (the number run) and relative_rms (per iteration, the first "
      "before any step, divided by the points' bounding-box diagonal).");
  m.def(
      "distance",
      [](const py::object& points, const py::object& to, const std::optional<Integer>& level, bool linear) {
        const Measurement m = measurement(points, to, level, linear, "points");
        return read_only(double_array(call_in_background(
            [m](CallControl& control) { return m.measure(control, false).distances; }, py::none(), false)));
      },
      py::arg("points"), py::arg("to"), py::arg("level") = py::none(), py::arg("linear") = false,
      "The distance from each point (an (n, 3) array, or a Mesh's vertices) to the limit surface of `to` (a Mesh, "
      "or a Surface whose kept plans are used), tessellated at `level` (1..64; None: 8, lower where that would make "
      "more than 2 million triangles); linear=True: to the mesh's faces. An (n,) read-only array.");
  m.def(
      "compare",
      [](const py::object& a, const py::object& b, const std::optional<Integer>& level, bool linear) {
        const Measurement m = measurement(a, b, level, linear, "a");
        if (m.points.empty()) throw py::value_error("a: has no points to measure");
        const auto [s, angles] = call_in_background(
            [m](CallControl& control) {
              const Measured measured = m.measure(control, true);
              const double length = bounding_box_diagonal(m.points);
              return std::pair(summarise_distances(measured.distances, length),
                               summarise_angles(measured.normal_angles, m.points.size()));
            },
            py::none(), false);
        py::dict out;
        out["count"] = s.count;
        out["rms"] = s.rms;
        out["percentile_99"] = s.percentile_99;
        out["max"] = s.max;
        out["length"] = s.length;
        out["relative_rms"] = s.relative_rms();
        out["relative_percentile_99"] = s.relative_percentile_99();
        out["relative_max"] = s.relative_max();
        out["normal_count"] = angles.count;
        out["normal_rms_degrees"] = angles.count > 0 ? angles.rms : NAN;
        out["normal_max_degrees"] = angles.count > 0 ? angles.max : NAN;
        return out;
      },
      py::arg("a"), py::arg("b"), py::arg("level") = py::none(), py::arg("linear") = false,
      "As gpsurf compare: the distances from the points of `a` (a Mesh's vertices or an (n, 3) array) to the limit "
      "surface of `b` (a Mesh or Surface; linear=True: its faces) summarised as a dict: count, rms, percentile_99, "
      "max (absolute), length (the points' bounding-box diagonal) and relative_rms, relative_percentile_99, "
      "relative_max (divided by it; NaN where the points lie at one place); and how far the normals turn: normal_count "
      "(the points with a normal: a Mesh's "
      "vertices on a face, area-weighted over them, but none where its faces meet at a sharp edge or corner; an "
      "array's points have none), normal_rms_degrees and "
      "normal_max_degrees (the angles, as lines 0..90, between their normals and the surface's at the nearest point; "
      "NaN where no point has a normal).");
}

}  // namespace gps::python
