// gpsurf.Surface (a mesh's plans and their exact evaluation) and gpsurf.tessellate.
#include <pybind11/stl.h>

#include "core/evaluation/surface_samples.h"
#include "core/evaluation/patch_eval.h"
#include "core/evaluation/tessellator.h"
#include "core/mesh/covariance_mesh.h"
#include "core/support/error.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/plans/patch_faces.h"
#include "core/plans/planned_surface.h"
#include "python/arrays.h"
#include "python/background_call.h"
#include "python/bindings.h"
#include "python/handles.h"

namespace gps::python {
namespace {

// How many points evaluate() computes between checks for a stop.
constexpr size_t kPointsBetweenChecks = 4096;

SurfaceHandle make_surface(const MeshHandle& mesh, const std::string& scheme, const std::string& loop_beta,
                           const Integer& depth, bool approximate) {
  const PlanOptions options = plan_options_named(scheme, loop_beta, to_int(depth, "depth"), approximate);
  return call_in_background([options, source = mesh.mesh](CallControl&) { return plan_surface(source, options); },
                            py::none(), false);
}

// Positions, du, dv, normals (and covariances) at (patches[i], u[i], v[i]); NaN rows where the
// point is undefined (q̂ left the positive definite cone).
py::tuple evaluate(const SurfaceHandle& h, const py::object& patches, const DoubleArray& u, const DoubleArray& v,
                   bool covariances) {
  const PatchPlans& plans = h.surface->tables().plans;
  std::vector<int> p = indices_of(patches, plans.n_patches(), "patches");
  const bool scalar_patch = py::array::ensure(patches).ndim() == 0;
  if (u.ndim() > 1 || v.ndim() > 1) throw py::value_error("u and v: expected numbers or 1D arrays");
  const size_t n = !scalar_patch ? p.size() : u.ndim() == 1 ? size_t(u.size()) : v.ndim() == 1 ? size_t(v.size()) : 1;
  if (scalar_patch) p.assign(n, p[0]);
  const auto us = broadcast(u, n, "u"), vs = broadcast(v, n, "v");
  for (size_t i = 0; i < n; ++i)
    if (!(us[i] >= 0 && vs[i] >= 0 && us[i] <= 1 && vs[i] <= 1 &&
          (plans.shape == PatchShape::quad || us[i] + vs[i] <= 1)))
      throw py::value_error("(u, v) = (" + py::repr(py::float_(us[i])).cast<std::string>() + ", " +
                            py::repr(py::float_(vs[i])).cast<std::string>() + ") at " + std::to_string(i) +
                            " lies outside the patch's domain");
  struct Samples {
    std::vector<Vec3> position, du, dv, normal;
    std::vector<Mat3> covariance;
  };
  const auto work = [surface = std::shared_ptr<const PlannedSurface>(h.surface), p = std::move(p), us,
                     vs](CallControl& control) {
    const Vec3 nan = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    Samples out{std::vector<Vec3>(p.size(), nan), std::vector<Vec3>(p.size(), nan), std::vector<Vec3>(p.size(), nan),
                std::vector<Vec3>(p.size(), nan), std::vector<Mat3>(p.size(), Mat3::Constant(nan[0]))};
    for (size_t i = 0; i < p.size(); ++i) {
      if (i % kPointsBetweenChecks == 0) {
        control.throw_if_stopped();
        control.report(double(i) / double(p.size()));
      }
      if (const auto sample = evaluate_patch(*surface, p[i], us[i], vs[i])) {
        out.position[i] = sample->position, out.du[i] = sample->du, out.dv[i] = sample->dv;
        out.normal[i] = sample->normal, out.covariance[i] = sample->covariance;
      }
    }
    return out;
  };
  const Samples s = n <= kPointsBetweenChecks ? call_released(work) : call_in_background(work, py::none(), true);
  py::tuple result = py::make_tuple(read_only(rows_to_array(s.position)), read_only(rows_to_array(s.du)),
                                    read_only(rows_to_array(s.dv)), read_only(rows_to_array(s.normal)));
  if (!covariances) return result;
  return py::make_tuple(result[0], result[1], result[2], result[3], read_only(matrices_to_array(s.covariance)));
}

// The vertices whose Gaussian differs between two meshes of one topology.
std::vector<int> changed_vertices(const CovarianceMesh& before, const CovarianceMesh& after) {
  std::vector<int> changed;
  for (size_t i = 0; i < after.n_vertices(); ++i)
    if (before.mean(i) != after.mean(i) || before.covariances[i] != after.covariances[i]) changed.push_back(int(i));
  return changed;
}

// Why `after` cannot update a surface planned for `before` (another topology or sharpness), or "".
std::string topology_change(const CovarianceMesh& before, const CovarianceMesh& after) {
  if (before.n_vertices() != after.n_vertices())
    return std::to_string(after.n_vertices()) + " vertices, the surface's mesh " + std::to_string(before.n_vertices());
  const PolygonTopology &a = before.topology(), &b = after.topology();
  if (a.offsets != b.offsets || a.verts != b.verts) return "other faces than the surface's mesh";
  if (!(before.sharpness == after.sharpness)) return "other creases or corners than the surface's mesh";
  return "";
}

void update(SurfaceHandle& h, const MeshHandle& mesh, const py::object& changed, bool replan) {
  const std::shared_ptr<const CovarianceMesh> after = mesh.mesh;
  if (const std::string why = topology_change(*h.mesh, *after); !why.empty()) {
    if (!replan) throw py::value_error("update: the mesh has " + why + "; pass replan=True to plan it anew");
    h = call_in_background([options = h.options, after](CallControl&) { return plan_surface(after, options); },
                           py::none(), false);
    return;
  }
  const std::vector<int> edited = changed_vertices(*h.mesh, *after);
  if (!changed.is_none()) {
    std::vector<int> named = indices_of(changed, int(after->n_vertices()), "changed");
    std::sort(named.begin(), named.end());
    for (const int v : edited)
      if (!std::binary_search(named.begin(), named.end(), v))
        throw py::value_error("update: vertex " + std::to_string(v) + "'s Gaussian changed but is not in `changed`");
  }
  if (edited.empty()) return;
  // A surface still read by a call in the background is left to it; this one updates a copy. The
  // GIL stays held, so that no other thread takes the surface while it changes (an update is short).
  if (h.surface.use_count() != 1) h.surface = std::make_shared<PlannedSurface>(*h.surface);
  h.surface->update(*after, edited);
  h.mesh = after;
}

// The surface tessellated at `level` (checked by the caller).
py::tuple tessellation(std::shared_ptr<const PlannedSurface> surface, int level) {
  const TriangleMesh t = call_in_background(
      [surface = std::move(surface), level](CallControl&) { return tessellate(*surface, level); }, py::none(), false);
  return py::make_tuple(read_only(rows_to_array(t.positions)), read_only(rows_to_array(t.normals)),
                        read_only(triangles_to_array(t.triangles)));
}

std::string describe(const SurfaceHandle& h) {
  return "<gpsurf.Surface: " + std::string(h.surface->scheme() == Scheme::loop ? "loop" : "catmull-clark") + ", " +
         std::to_string(h.surface->tables().plans.n_patches()) + " patches of a mesh of " +
         std::to_string(h.mesh->n_vertices()) + " vertices>";
}

}  // namespace

SurfaceHandle plan_surface(std::shared_ptr<const CovarianceMesh> mesh, const PlanOptions& options) {
  auto surface = std::make_shared<PlannedSurface>(*mesh, options);
  return SurfaceHandle{std::move(surface), std::move(mesh), options};
}

void add_surface_bindings(py::module_& m) {
  py::class_<SurfaceHandle>(m, "Surface",
                            "The GPS limit surface of a mesh: its plans and stencil tables, evaluated exactly.\n\n"
                            "Surface(mesh, scheme='auto', loop_beta='loop', depth=-1, approximate=False) plans the "
                            "surface of `mesh`: scheme 'auto' (Loop for a mesh of triangles, else Catmull-Clark), "
                            "'loop' or 'catmull-clark'; loop_beta 'loop' or 'warren'; depth -1 for the default; "
                            "approximate: the thesis' Bezier plans. Many threads may evaluate, tessellate or render "
                            "one Surface at once.")
      .def(py::init(&make_surface), py::arg("mesh"), py::arg("scheme") = "auto", py::arg("loop_beta") = "loop",
           py::arg("depth") = -1, py::arg("approximate") = false)
      // Read by the package's __init__, which refuses a second call: pybind11 would ignore it.
      .def_property_readonly("_initialised", [](const SurfaceHandle& h) { return initialised(h); })
      .def_property_readonly(
          "scheme",
          [](const SurfaceHandle& h) { return h.surface->scheme() == Scheme::loop ? "loop" : "catmull-clark"; },
          "'loop' or 'catmull-clark'")
      .def_property_readonly(
          "n_patches", [](const SurfaceHandle& h) { return h.surface->tables().plans.n_patches(); },
          "the number of patches")
      .def_property_readonly(
          "patch_corners", [](const SurfaceHandle& h) { return h.surface->tables().plans.corners(); },
          "4 (quads, domain [0,1]^2) or 3 (triangles, u, v >= 0, u + v <= 1)")
      .def_property_readonly(
          "patch_faces",
          [](const SurfaceHandle& h) {
            return read_only(int_array(patch_faces(h.mesh->topology(), h.surface->tables().plans)));
          },
          "the face of the mesh each patch lies on, an (n_patches,) read-only int32 array: one patch per quad or "
          "triangle, a face of k != 4 sides under Catmull-Clark k patches")
      .def_property_readonly(
          "mesh", [](const SurfaceHandle& h) { return MeshHandle{h.mesh}; },
          "the mesh the surface was planned or last updated for")
      .def("evaluate", &evaluate, py::arg("patches"), py::arg("u"), py::arg("v"), py::arg("covariances") = false,

           "The limit surface at (patch, u, v), each an integer/number or a 1D array (broadcast): (positions, du, "
           "dv, normals), (n, 3) read-only arrays, and with covariances=True also the (n, 3, 3) covariances of the "
           "limit Gaussians; NaN rows where the surface is undefined. Raises IndexError for a patch out of range, "
           "TypeError for a patch that is not an integer, ValueError for (u, v) outside the patch's domain.")
      .def("update", &update, py::arg("mesh"), py::arg("changed") = py::none(), py::arg("replan") = false,

           "Brings the surface up to `mesh`, a copy of its mesh whose Gaussians were edited: the 9D points of the "
           "vertices that changed and the stencil rows that read them. changed: the vertices edited (checked: a "
           "vertex that changed but is not named raises ValueError), None to find them. A mesh of another topology "
           "or sharpness raises ValueError unless replan=True, which plans the surface anew.")
      .def(
          "tessellate",
          [](const SurfaceHandle& h, const Integer& level) {
            return tessellation(h.surface, int_in(level, 1, 64, "level"));
          },
          py::arg("level") = 8,
          "Every patch evaluated at a uniform level (1..64) from the kept plans into a "
          "watertight triangle mesh: (points, normals, triangles), read-only arrays")
      .def("__repr__", &describe)
      // Pickled as its mesh and options, planned again when loaded (every protocol: 0 and 1 would
      // otherwise make the instance with object.__new__, which a compiled class refuses).
      .def("__reduce__", [](const SurfaceHandle& h) {
        const PlanOptions& o = h.options;
        const char* scheme = !o.scheme ? "auto" : *o.scheme == Scheme::loop ? "loop" : "catmull-clark";
        return py::make_tuple(py::module_::import("gpsurf").attr("Surface"),
                              py::make_tuple(MeshHandle{h.mesh}, scheme,
                                             o.loop_beta == LoopBeta::warren ? "warren" : "loop", o.depth, !o.exact));
      });

  m.def(
      "tessellate",
      [](const MeshHandle& mesh, const Integer& level, const std::string& scheme, const std::string& loop_beta,
         const Integer& depth, bool approximate) {
        const int checked = int_in(level, 1, 64, "level");  // before the surface is planned
        return tessellation(make_surface(mesh, scheme, loop_beta, depth, approximate).surface, checked);
      },
      py::arg("mesh"), py::arg("level") = 8, py::arg("scheme") = "auto", py::arg("loop_beta") = "loop",
      py::arg("depth") = -1, py::arg("approximate") = false,

      "Plans the surface of `mesh` and evaluates every patch at a uniform level (1..64) into a watertight triangle "
      "mesh: (points, normals, triangles), read-only arrays. Surface(mesh).tessellate(level) keeps the plans.");
}

}  // namespace gps::python
