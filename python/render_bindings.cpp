// gpsurf.render: the GPU renderer off-screen (OSMesa or EGL), as `gpsurf render` draws; images as
// float32 numpy arrays, and read_image / write_image through OpenImageIO.
#include <pybind11/stl.h>

#include <optional>

#include "core/mesh/covariance_mesh.h"
#include "core/mesh/error.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "render/gl/gl_context.h"
#include "render/gl/render_target.h"
#include "render/image/image_io.h"
#include "render/image/matcap_file.h"
#include "render/pipeline/render_framing.h"
#include "render/pipeline/surface_renderer.h"
#include "view/camera.h"

namespace gps::python {
namespace {

using FloatImage = py::array_t<float, py::array::c_style | py::array::forcecast>;

FloatImage to_array(const Image& image) {
  FloatImage a({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(image.channels)});
  std::copy(image.pixels.begin(), image.pixels.end(), a.mutable_data());
  return a;
}

Image to_image(const FloatImage& a) {
  if (a.ndim() != 3 || a.shape(2) < 1 || a.shape(2) > 4)
    throw py::value_error("image: expected a height x width x channels array (1 to 4 channels)");
  Image image{int(a.shape(1)), int(a.shape(0)), int(a.shape(2)), {}};
  image.pixels.assign(a.data(), a.data() + a.size());
  return image;
}

ShadingMode shading_named(const std::string& mode) {
  if (mode == "matcap") return ShadingMode::matcap;
  if (mode == "normals") return ShadingMode::normals;
  if (mode == "flat") return ShadingMode::flat;
  throw py::value_error("mode: expected 'matcap', 'normals' or 'flat', got '" + mode + "'");
}

ContextKind context_named(const std::string& name) {
  if (name == "auto") return ContextKind::automatic;
  if (name == "osmesa") return ContextKind::osmesa;
  if (name == "egl") return ContextKind::egl;
  throw py::value_error("context: expected 'auto', 'osmesa' or 'egl', got '" + name + "'");
}

FloatImage render(const CovarianceMesh& mesh, int width, int height, int level, float pixels, const std::string& matcap,
                  const std::string& mode, std::optional<std::vector<float>> camera, bool mesh_lines, bool wireframe,
                  bool ellipsoids, float sigma, std::vector<float> background, const std::string& scheme,
                  const std::string& loop_beta, const std::string& context) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw py::value_error("width and height: expected 1..16384, got " + std::to_string(width) + "x" +
                          std::to_string(height));
  if (level < 0 || level > 64)
    throw py::value_error("level: expected 1..64 (0: adaptive), got " + std::to_string(level));
  if (camera && camera->size() != 2 && camera->size() != 3)
    throw py::value_error("camera: expected (yaw, pitch) or (yaw, pitch, distance) in degrees");
  if (background.size() != 3) throw py::value_error("background: expected (r, g, b)");
  const PlanOptions plans = plan_options_named(scheme, loop_beta);
  DrawOptions o;
  set_render_tessellation(o, level, pixels, width, height);
  o.mode = shading_named(mode);
  o.mesh_lines = mesh_lines;
  o.wireframe = wireframe;
  o.ellipsoids = ellipsoids;
  o.sigma_scale = sigma;
  o.background = {background[0], background[1], background[2]};
  const Image matcap_image = load_matcap(matcap);
  const ContextKind kind = context_named(context);
  Image color;
  {
    py::gil_scoped_release unlocked;  // other Python threads run while the frame is drawn
    const auto gl = create_offscreen_context(kind);
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh, plans);
    renderer.set_matcap(matcap_image);
    RenderTarget target(width, height);
    renderer.draw(target, render_camera(renderer, mesh, camera.value_or(std::vector<float>{}), 1, o, width, height), o);
    color = target.read(0);
  }
  return to_array(color);
}

}  // namespace

void add_render_bindings(py::module_& m) {
  m.def("render", &render, py::arg("mesh"), py::arg("width") = 800, py::arg("height") = 600, py::arg("level") = 0,
        py::arg("pixels") = 0.0f, py::arg("matcap") = "clay", py::arg("mode") = "matcap",
        py::arg("camera") = py::none(), py::arg("mesh_lines") = false, py::arg("wireframe") = false,
        py::arg("ellipsoids") = false, py::arg("sigma") = 1.0f, py::arg("background") = std::vector<float>{1, 1, 1},
        py::arg("scheme") = "auto", py::arg("loop_beta") = "loop", py::arg("context") = "auto",
        "The limit surface drawn off-screen as `gpsurf render` draws it: a height x width x 4 float32 RGBA array in "
        "[0, 1], top row first. level 0: adaptive (pixels: target edge length, 0 for the default); camera: (yaw, "
        "pitch[, distance]) in degrees, None to frame the mesh; matcap: clay, porcelain, jade, red-wax or an image "
        "file");
  m.def(
      "read_image", [](const std::string& path) { return to_array(read_image(path)); }, py::arg("path"),
      "An image file (PNG, EXR, ...) as a height x width x channels float32 array");
  m.def(
      "write_image", [](const std::string& path, const FloatImage& image) { write_image(path, to_image(image)); },
      py::arg("path"), py::arg("image"), "Writes a height x width x channels float array (PNG: 8 bits, EXR: float)");
}

}  // namespace gps::python
