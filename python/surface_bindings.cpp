// gpsurf.Surface (a mesh's plans and their exact evaluation) and gpsurf.tessellate.
#include <pybind11/stl.h>

#include <numeric>

#include "core/evaluation/patch_eval.h"
#include "core/evaluation/tessellator.h"
#include "core/mesh/covariance_mesh.h"
#include "core/plans/planned_surface.h"
#include "python/arrays.h"
#include "python/bindings.h"

namespace gps::python {
namespace {

// Positions, du, dv and normals at (patches[i], u[i], v[i]); NaN rows where the point is undefined
// (q̂ left the positive definite cone).
py::tuple evaluate(const PlannedSurface& s, const py::array_t<int, py::array::c_style | py::array::forcecast>& patches,
                   const DoubleArray& u, const DoubleArray& v) {
  const size_t n =
      patches.ndim() == 0 ? std::max(u.ndim() == 0 ? 1 : size_t(u.size()), size_t(1)) : size_t(patches.size());
  if (patches.ndim() > 1) throw py::value_error("patches: expected a number or a 1D array");
  std::vector<int> p(n);
  if (patches.ndim() == 0)
    std::fill(p.begin(), p.end(), *patches.data());
  else
    std::copy(patches.data(), patches.data() + n, p.begin());
  const auto us = broadcast(u, n, "u"), vs = broadcast(v, n, "v");
  const PatchPlans& plans = s.tables().plans;
  const Vec3 nan = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  std::vector<Vec3> position(n, nan), du(n, nan), dv(n, nan), normal(n, nan);
  for (size_t i = 0; i < n; ++i) {
    if (p[i] < 0 || p[i] >= plans.n_patches())
      throw py::index_error("patch " + std::to_string(p[i]) + " out of range 0.." +
                            std::to_string(plans.n_patches() - 1));
    if (!(us[i] >= 0 && vs[i] >= 0 && us[i] <= 1 && vs[i] <= 1 &&
          (plans.shape == PatchShape::quad || us[i] + vs[i] <= 1)))
      throw py::value_error("(u, v) = (" + std::to_string(us[i]) + ", " + std::to_string(vs[i]) +
                            ") lies outside the patch's domain");
    if (const auto sample = evaluate_patch(plans, s.points(), p[i], us[i], vs[i])) {
      position[i] = sample->position, du[i] = sample->du, dv[i] = sample->dv, normal[i] = sample->normal;
    }
  }
  return py::make_tuple(rows_to_array(position), rows_to_array(du), rows_to_array(dv), rows_to_array(normal));
}

}  // namespace

void add_surface_bindings(py::module_& m) {
  py::class_<PlannedSurface>(m, "Surface",
                             "The GPS limit surface of a mesh: its plans and stencil tables, evaluated exactly")
      .def(py::init([](const CovarianceMesh& mesh, const std::string& scheme, const std::string& loop_beta, int depth,
                       bool approximate) {
             return PlannedSurface(mesh, plan_options_named(scheme, loop_beta, depth, approximate));
           }),
           py::arg("mesh"), py::arg("scheme") = "auto", py::arg("loop_beta") = "loop", py::arg("depth") = -1,
           py::arg("approximate") = false,
           "Plans the surface of `mesh`: scheme 'auto' (Loop for a mesh of triangles, else Catmull-Clark), 'loop' "
           "or 'catmull-clark'; depth -1 for the default; approximate: the thesis' Bezier plans")
      .def_property_readonly(
          "scheme", [](const PlannedSurface& s) { return s.scheme() == Scheme::loop ? "loop" : "catmull-clark"; })
      .def_property_readonly("n_patches", [](const PlannedSurface& s) { return s.tables().plans.n_patches(); })
      .def_property_readonly(
          "patch_corners", [](const PlannedSurface& s) { return s.tables().plans.corners(); },
          "4 (quads, domain [0,1]^2) or 3 (triangles, u, v >= 0, u + v <= 1)")
      .def("evaluate", &evaluate, py::arg("patches"), py::arg("u"), py::arg("v"),
           "The limit surface at (patch, u, v), each a number or a 1D array: (positions, du, dv, normals), n x 3 "
           "arrays; NaN rows where the surface is undefined")
      .def(
          "update",
          [](PlannedSurface& s, const CovarianceMesh& mesh, std::optional<std::vector<int>> changed) {
            if (!changed) {
              changed.emplace(mesh.n_vertices());
              std::iota(changed->begin(), changed->end(), 0);
            }
            for (const int v : *changed)
              if (v < 0 || size_t(v) >= mesh.n_vertices())
                throw py::index_error("vertex " + std::to_string(v) + " out of range");
            s.update(mesh, *changed);
          },
          py::arg("mesh"), py::arg("changed") = py::none(),
          "After the Gaussians of `changed` vertices of `mesh` (same topology) were edited (all when None): their 9D "
          "points and the stencil rows that read them");

  m.def(
      "tessellate",
      [](const CovarianceMesh& mesh, int level, const std::string& scheme, const std::string& loop_beta, int depth,
         bool approximate) {
        if (level < 1 || level > 64) throw py::value_error("level: expected 1..64, got " + std::to_string(level));
        const PlannedSurface s(mesh, plan_options_named(scheme, loop_beta, depth, approximate));
        const TriangleMesh t = tessellate(s.tables().plans, s.points(), level);
        return py::make_tuple(rows_to_array(t.positions), rows_to_array(t.normals), triangles_to_array(t.triangles));
      },
      py::arg("mesh"), py::arg("level") = 8, py::arg("scheme") = "auto", py::arg("loop_beta") = "loop",
      py::arg("depth") = -1, py::arg("approximate") = false,
      "Every patch evaluated at a uniform level into a watertight triangle mesh: (points, normals, triangles)");
}

}  // namespace gps::python
