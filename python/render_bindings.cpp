// gpsurf.render: the GPU renderer off-screen (OSMesa or EGL), as `gpsurf render` draws; images as
// float32 numpy arrays, and read_image / write_image (render/image/image_io.h).
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <optional>

#include "core/fitting/limit_scalars.h"
#include "core/io/mesh_io.h"
#include "core/mesh/covariance_mesh.h"
#include "core/support/error.h"
#include "python/arrays.h"
#include "python/background_call.h"
#include "python/bindings.h"
#include "python/handles.h"
#include "render/gl/gl_context.h"
#include "render/gl/render_target.h"
#include "render/image/image_io.h"
#include "render/image/matcap_file.h"
#include "render/image/scalar_colouring.h"
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

// Refuses an image with a channel that is not finite, which every format but EXR (8 or 16 bits a
// channel) would write as black.
void refuse_non_finite(const Image& image) {
  const auto bad = std::find_if(image.pixels.begin(), image.pixels.end(), [](float c) { return !std::isfinite(c); });
  if (bad == image.pixels.end()) return;
  const size_t pixel = size_t(bad - image.pixels.begin()) / size_t(image.channels);
  throw py::value_error("image: pixel (" + std::to_string(pixel / size_t(image.width)) + ", " +
                        std::to_string(pixel % size_t(image.width)) + ") is not finite, which only .exr holds");
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

// A render's width or height.
int image_side(const Integer& side, const char* what) { return int_in(side, 1, RenderTarget::kLargestSide, what); }

// What render() and Surface.render() take besides the surface: width, height (image_side) and level
// (0..64, 0: adaptive) checked by the bindings, the rest by render().
struct RenderSettings {
  int width, height, level;
  float pixels;
  std::string matcap, mode;
  std::optional<std::vector<float>> camera;
  bool mesh_lines, wireframe, ellipsoids;
  float sigma;
  std::vector<float> background;
  std::string context;
  std::optional<std::vector<double>> scalars;  // one per control vertex
  std::string colormap;
  std::optional<std::vector<double>> scalar_range;  // (low, high); None: the scalars' own
};

// The (low, high) the scalars are mapped over, checked with the scalars against `mesh`.
std::array<double, 2> checked_scalar_range(const CovarianceMesh& mesh, const RenderSettings& r) {
  if (!is_colormap(r.colormap))
    throw py::value_error("colormap: expected 'viridis', 'coolwarm' or 'gray', got '" + r.colormap + "'");
  if (!r.scalars) {
    if (r.scalar_range) throw py::value_error("scalar_range: given without scalars");
    return {0, 1};
  }
  const std::vector<double>& s = *r.scalars;
  if (s.size() != mesh.n_vertices())
    throw py::value_error("scalars: expected one per vertex (" + std::to_string(mesh.n_vertices()) + "), got " +
                          std::to_string(s.size()));
  for (size_t i = 0; i < s.size(); ++i)
    if (!std::isfinite(s[i]))
      throw py::value_error("scalars: the scalar of vertex " + std::to_string(i) + " is not finite");
  if (r.scalar_range) {
    const std::vector<double>& range = *r.scalar_range;
    if (range.size() != 2 || !std::isfinite(range[0]) || !std::isfinite(range[1]) || !(range[0] < range[1]))
      throw py::value_error("scalar_range: expected (low, high), finite, low < high");
    return {range[0], range[1]};
  }
  if (s.empty()) return {0, 1};
  const auto [low, high] = std::minmax_element(s.begin(), s.end());
  return {*low, *high};
}

// The surface `plans` (planned for `mesh`, or planned here under `options` when empty) drawn off-screen.
FloatImage render(std::shared_ptr<const CovarianceMesh> mesh, std::shared_ptr<const PlannedSurface> plans,
                  const PlanOptions& options, const RenderSettings& r) {
  if (!std::isfinite(r.pixels) || r.pixels < 0)
    throw py::value_error("pixels: expected a finite number >= 0 (0: the default)");
  if (r.camera && r.camera->size() != 2 && r.camera->size() != 3)
    throw py::value_error("camera: expected (yaw, pitch) or (yaw, pitch, distance) in degrees");
  if (r.camera)
    for (const float c : *r.camera)
      if (!std::isfinite(c)) throw py::value_error("camera: expected finite numbers");
  if (r.camera && r.camera->size() == 3 && !((*r.camera)[2] > 0))
    throw py::value_error("camera: the distance must be above 0");
  if (r.background.size() != 3) throw py::value_error("background: expected (r, g, b)");
  for (const float c : r.background)
    if (!(c >= 0 && c <= 1)) throw py::value_error("background: expected (r, g, b) in [0, 1]");
  if (!(std::isfinite(r.sigma) && r.sigma > 0)) throw py::value_error("sigma: expected a finite number above 0");
  DrawOptions o;
  set_render_tessellation(o, r.level, r.pixels, r.width, r.height);
  o.mode = shading_named(r.mode);
  o.mesh_lines = r.mesh_lines;
  o.wireframe = r.wireframe;
  o.ellipsoids = r.ellipsoids;
  o.sigma_scale = r.sigma;
  o.background = {r.background[0], r.background[1], r.background[2]};
  o.surface_cache = false;  // one image: captured triangles would never be drawn again
  const ContextKind kind = context_named(r.context);
  const std::array<double, 2> range = checked_scalar_range(*mesh, r);
  Image matcap_image = load_matcap(r.matcap);
  const Image color = call_in_background(
      [=, matcap_image = std::move(matcap_image)](CallControl&) {
        // One render at a time: Mesa's EGL and OSMesa do not make contexts from several threads at once.
        static std::mutex one_context;
        const std::lock_guard<std::mutex> only(one_context);
        const auto gl = create_offscreen_context(kind);
        SurfaceRenderer renderer;
        if (plans)
          renderer.set_mesh(*mesh, *plans);
        else
          renderer.set_mesh(*mesh, options);
        renderer.set_matcap(matcap_image);
        RenderTarget target(r.width, r.height);
        renderer.draw(target,
                      render_camera(renderer, *mesh, r.camera.value_or(std::vector<float>{}), 1, o, r.width, r.height),
                      o);
        Image colour = target.read(0);
        if (r.scalars) {
          const std::shared_ptr<const PlannedSurface> surface =
              plans ? plans : std::make_shared<const PlannedSurface>(*mesh, options);
          colour_by_scalars(colour, target.read(1), r.colormap, range[0], range[1],
                            [&](const std::vector<Vec3>& at) { return limit_scalars_at(*surface, *r.scalars, at); });
        }
        return colour;
      },
      py::none(), false);
  return to_array(color);
}

constexpr const char* kRenderDoc =
    "The limit surface drawn off-screen as `gpsurf render` draws it: a height x width x 4 float32 RGBA array in [0, "
    "1], top row first. level 0: adaptive (pixels: target edge length, 0 for the default); camera: (yaw, pitch[, "
    "distance]) in degrees, None to frame the mesh; matcap: clay, porcelain, jade, red-wax or an image file (str or "
    "os.PathLike); mode: matcap, normals or flat; mesh_lines, wireframe, ellipsoids (sigma: their scale) overlays; "
    "background: (r, g, b) in [0, 1]; context: auto, osmesa or egl. scalars: one number per control vertex, carried "
    "to the limit surface as a primvar (the same limit weights as the points) and drawn through colormap (viridis, "
    "coolwarm or gray) over scalar_range (low, high; None: the scalars' least and greatest), shaded by the surface's "
    "brightness.";

}  // namespace

void add_render_bindings(py::module_& m) {
  m.def(
      "render",
      [](const MeshHandle& mesh, const Integer& width, const Integer& height, const Integer& level, float pixels,
         const py::object& matcap, const std::string& mode, std::optional<std::vector<float>> camera, bool mesh_lines,
         bool wireframe, bool ellipsoids, float sigma, std::vector<float> background, const std::string& scheme,
         const std::string& loop_beta, const std::string& context, std::optional<std::vector<double>> scalars,
         const std::string& colormap, std::optional<std::vector<double>> scalar_range) {
        return render(mesh.mesh, nullptr, plan_options_named(scheme, loop_beta),
                      {image_side(width, "width"), image_side(height, "height"), int_in(level, 0, 64, "level"), pixels,
                       path_of(matcap, "matcap"), mode, camera, mesh_lines, wireframe, ellipsoids, sigma, background,
                       context, std::move(scalars), colormap, std::move(scalar_range)});
      },
      py::arg("mesh"), py::arg("width") = 800, py::arg("height") = 600, py::arg("level") = 0, py::arg("pixels") = 0.0f,
      py::arg("matcap") = "clay", py::arg("mode") = "matcap", py::arg("camera") = py::none(),
      py::arg("mesh_lines") = false, py::arg("wireframe") = false, py::arg("ellipsoids") = false,
      py::arg("sigma") = 1.0f, py::arg("background") = std::vector<float>{1, 1, 1}, py::arg("scheme") = "auto",
      py::arg("loop_beta") = "loop", py::arg("context") = "auto", py::arg("scalars") = py::none(),
      py::arg("colormap") = "viridis", py::arg("scalar_range") = py::none(), kRenderDoc);
  const py::object surface_class = m.attr("Surface");
  surface_class.attr("render") = py::cpp_function(
      [](const SurfaceHandle& s, const Integer& width, const Integer& height, const Integer& level, float pixels,
         const py::object& matcap, const std::string& mode, std::optional<std::vector<float>> camera, bool mesh_lines,
         bool wireframe, bool ellipsoids, float sigma, std::vector<float> background, const std::string& context,
         std::optional<std::vector<double>> scalars, const std::string& colormap,
         std::optional<std::vector<double>> scalar_range) {
        return render(s.mesh, s.surface, s.options,
                      {image_side(width, "width"), image_side(height, "height"), int_in(level, 0, 64, "level"), pixels,
                       path_of(matcap, "matcap"), mode, camera, mesh_lines, wireframe, ellipsoids, sigma, background,
                       context, std::move(scalars), colormap, std::move(scalar_range)});
      },
      py::name("render"), py::is_method(surface_class), py::sibling(py::getattr(surface_class, "render", py::none())),
      py::arg("width") = 800, py::arg("height") = 600, py::arg("level") = 0, py::arg("pixels") = 0.0f,
      py::arg("matcap") = "clay", py::arg("mode") = "matcap", py::arg("camera") = py::none(),
      py::arg("mesh_lines") = false, py::arg("wireframe") = false, py::arg("ellipsoids") = false,
      py::arg("sigma") = 1.0f, py::arg("background") = std::vector<float>{1, 1, 1}, py::arg("context") = "auto",
      py::arg("scalars") = py::none(), py::arg("colormap") = "viridis", py::arg("scalar_range") = py::none(),
      "As gpsurf.render draws a mesh, from the surface's kept plans (its own scheme): a height x width x 4 float32 "
      "RGBA array.");
  m.def(
      "read_image",
      [](const py::object& path) {
        const std::string file = path_of(path);
        return to_array(call_in_background([file](CallControl&) { return read_image(file); }, py::none(), false));
      },
      py::arg("path"), "An image file (PNG, EXR, ...) as a height x width x channels float32 array");
  m.def(
      "write_image",
      [](const py::object& path, const FloatImage& image) {
        const std::string file = path_of(path);
        const Image pixels = to_image(image);
        if (extension_of(file) != ".exr") refuse_non_finite(pixels);
        without_gil([&] { write_image(file, pixels); });
      },
      py::arg("path"), py::arg("image"),
      "Writes a height x width x channels float array (PNG: 8 bits, EXR: float); a pixel that is not finite, which "
      "only EXR holds, raises ValueError for the other formats");
}

}  // namespace gps::python
