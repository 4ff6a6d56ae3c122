#pragma once
// The parts of the Python module `gpsurf`, each adding its functions and classes to it.
#include <pybind11/pybind11.h>

namespace gps::python {

/// Mesh, read, samples, infer, subdivide, edit, simplify.
void add_mesh_bindings(pybind11::module_& m);
/// Surface (plans and their evaluation), tessellate.
void add_surface_bindings(pybind11::module_& m);
/// fit, distance, compare.
void add_fitting_bindings(pybind11::module_& m);
/// render, Surface.render, read_image, write_image (the GPU renderer, off-screen).
void add_render_bindings(pybind11::module_& m);

}  // namespace gps::python
