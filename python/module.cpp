// The Python module `gpsurf`: covariance meshes, the exact reference, plans and their evaluation,
// and (where built with GL) off-screen renders, with numpy arrays in and out. gps::Error becomes
// gpsurf.Error with the same one-line message.
#include <pybind11/pybind11.h>

#include "core/mesh/error.h"
#include "core/version.h"
#include "python/bindings.h"

PYBIND11_MODULE(gpsurf, m) {
  m.doc() = "Gaussian-Product Subdivision surfaces: covariance meshes, exact subdivision and evaluation, rendering";
  m.attr("__version__") = gps::kVersion;
  pybind11::register_exception<gps::Error>(m, "Error", PyExc_RuntimeError);
  gps::python::add_mesh_bindings(m);
  gps::python::add_surface_bindings(m);
#ifdef GPSURF_WITH_GL
  gps::python::add_render_bindings(m);
#endif
}
