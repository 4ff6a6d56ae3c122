// The extension module gpsurf._gpsurf behind the package gpsurf (python/gpsurf/__init__.py):
// covariance meshes, the exact reference, plans and their evaluation, fitting and distances, and
// (where built with GL) off-screen renders, with numpy arrays in and out. gps::Error becomes
// gpsurf.Error with the same one-line message; a cancelled call raises gpsurf.Cancelled.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <exception>
#include <new>

#include "core/support/error.h"
#include "core/support/freed_memory.h"
#include "core/support/progress.h"
#include "core/version.h"
#include "python/bindings.h"

PYBIND11_MODULE(_gpsurf, m) {
  m.doc() =
      "Gaussian-Product Subdivision surfaces: covariance meshes, exact subdivision and evaluation, fitting, "
      "rendering";
  m.attr("__version__") = gps::kVersion;
  // As gpsurf's programs do: the large blocks a modelling operation or a plan frees are kept for the
  // next call, where glibc would otherwise map and zero each one afresh (core/support/freed_memory.h).
  gps::keep_freed_memory();
  // numpy's C API is set up here, with the GIL held once: two threads making the first array at once
  // would otherwise wait on each other (pybind11 sets it up on first use, under the GIL).
  pybind11::detail::npy_api::get();
  // Out of memory in the words of the rest of the module, not "std::bad_alloc".
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::bad_alloc&) {
      PyErr_SetString(PyExc_MemoryError, "out of memory: the arguments ask for more than this machine can hold");
    }
  });
  const auto error = pybind11::register_exception<gps::Error>(m, "Error", PyExc_RuntimeError);
  pybind11::register_exception<gps::Cancelled>(m, "Cancelled", error.ptr());
  gps::python::add_mesh_bindings(m);
  gps::python::add_surface_bindings(m);
  gps::python::add_fitting_bindings(m);
#ifdef GPSURF_WITH_GL
  gps::python::add_render_bindings(m);
#endif
}
