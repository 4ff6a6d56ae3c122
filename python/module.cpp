// The extension module gpsurf._gpsurf behind the package gpsurf (python/gpsurf/__init__.py):
// covariance meshes, the exact reference, plans and their evaluation, fitting and distances, and
// (where built with GL) off-screen renders, with numpy arrays in and out. gps::Error becomes
// gpsurf.Error with the same one-line message; a cancelled call raises gpsurf.Cancelled.
#include <pybind11/pybind11.h>

#include "core/support/error.h"
#include "core/support/progress.h"
#include "core/version.h"
#include "python/bindings.h"

PYBIND11_MODULE(_gpsurf, m) {
  m.doc() =
      "Gaussian-Product Subdivision surfaces: covariance meshes, exact subdivision and evaluation, fitting, "
      "rendering";
  m.attr("__version__") = gps::kVersion;
  const auto error = pybind11::register_exception<gps::Error>(m, "Error", PyExc_RuntimeError);
  pybind11::register_exception<gps::Cancelled>(m, "Cancelled", error.ptr());
  gps::python::add_mesh_bindings(m);
  gps::python::add_surface_bindings(m);
  gps::python::add_fitting_bindings(m);
#ifdef GPSURF_WITH_GL
  gps::python::add_render_bindings(m);
#endif
}
