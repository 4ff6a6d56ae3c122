// gpsurf render IN -o OUT.png: a headless render of the GPS limit surface (OSMesa, no display).
#include <iostream>
#include <regex>
#include <sstream>

#include "app/commands.h"
#include "core/error.h"
#include "core/mesh_io.h"
#include "render/gl_context.h"
#include "render/matcap.h"
#include "render/reference_triangles.h"
#include "render/surface_renderer.h"

namespace gps {

namespace {

struct RenderArgs {
  std::string input, output, size = "800x600", matcap = "clay", mode = "matcap", camera, background = "1,1,1";
  std::vector<std::string> aovs;
  int level = 8, depth = 3, reference = -1;
  float pixels = 0;
  bool mesh_lines = false, wireframe = false, ellipsoids = false;
  float sigma = 1.0f;
};

std::vector<float> parse_floats(const std::string& text, const char* what, size_t min_count, size_t max_count) {
  std::vector<float> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    try {
      size_t used = 0;
      values.push_back(std::stof(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw usage_error(std::string(what) + ": '" + text + "' is not a comma-separated list of numbers");
    }
  }
  if (values.size() < min_count || values.size() > max_count)
    throw usage_error(std::string(what) + ": expected " + std::to_string(min_count) + " to " + std::to_string(max_count) + " numbers, got '" + text + "'");
  return values;
}

void render(const RenderArgs& a) {
  std::smatch size_match;
  if (!std::regex_match(a.size, size_match, std::regex(R"((\d{1,5})x(\d{1,5}))"))) throw usage_error("--size: expected WxH, got '" + a.size + "'");
  const int width = std::stoi(size_match[1]), height = std::stoi(size_match[2]);
  std::string position_aov, normal_aov;
  for (const auto& aov : a.aovs) {
    const auto eq = aov.find('=');
    const std::string kind = aov.substr(0, eq), file = eq == std::string::npos ? "" : aov.substr(eq + 1);
    if (file.empty() || (kind != "position" && kind != "normal")) throw usage_error("--aov: expected position=FILE.exr or normal=FILE.exr, got '" + aov + "'");
    (kind == "position" ? position_aov : normal_aov) = file;
  }
  const auto bg = parse_floats(a.background, "--background", 3, 3);
  const Image matcap = load_matcap(a.matcap);  // before any GL work: a bad name is a usage error
  const CovarianceMesh mesh = read_mesh(a.input);

  const auto context = create_offscreen_context();
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh, a.depth);
  renderer.set_matcap(matcap);
  DrawOptions o;
  o.level = float(a.level);
  o.pixels = a.pixels;
  o.mode = a.mode == "normals" ? ShadingMode::normals : a.mode == "flat" ? ShadingMode::flat : ShadingMode::matcap;
  o.mesh_lines = a.mesh_lines;
  o.wireframe = a.wireframe;
  o.ellipsoids = a.ellipsoids;
  o.sigma_scale = a.sigma;
  o.background = {bg[0], bg[1], bg[2]};
  if (a.reference >= 0) {
    renderer.set_triangles(reference_triangles(mesh, a.reference));
    o.static_triangles = true;
  }
  Vec3 lo = mesh.mean(0), hi = lo;
  for (size_t i = 1; i < mesh.n_vertices(); ++i) lo = lo.cwiseMin(mesh.mean(i)), hi = hi.cwiseMax(mesh.mean(i));
  Camera camera = frame_box(lo, hi);
  if (!a.camera.empty()) {
    const auto c = parse_floats(a.camera, "--camera", 2, 3);
    const float distance = camera.distance;
    camera = frame_box(lo, hi, c[0], c[1]);
    camera.distance = c.size() > 2 ? c[2] : distance;
  }
  RenderTarget target(width, height);
  renderer.draw(target, camera, o);
  Image color = target.read(0);
  write_image(a.output, color);
  if (!position_aov.empty()) write_image(position_aov, target.read(1));
  if (!normal_aov.empty()) write_image(normal_aov, target.read(2));
  std::cout << "wrote " << a.output << " (" << width << "x" << height << ", " << renderer.tables().plans.n_patches() << " patches, "
            << context->description() << ")\n";
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  auto* cmd = app.add_subcommand("render", "Render the limit surface without a display (OSMesa)");
  cmd->add_option("input", a->input, "input mesh")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", a->output, "output image (.png)")->required();
  cmd->add_option("--size", a->size, "image size WxH");
  auto* level = cmd->add_option("--level", a->level, "uniform tessellation level")->check(CLI::Range(1, 64));
  cmd->add_option("--pixels", a->pixels, "adaptive tessellation: target edge length in pixels")->check(CLI::Range(0.5f, 1000.0f))->excludes(level);
  cmd->add_option("--depth", a->depth, "maximum plan depth")->check(CLI::Range(1, 8));
  cmd->add_option("--matcap", a->matcap, "built-in MatCap (" + [] {
    std::string s;
    for (const auto& n : builtin_matcap_names()) s += (s.empty() ? "" : ", ") + n;
    return s;
  }() + ") or an image file");
  cmd->add_option("--mode", a->mode, "shading")->check(CLI::IsMember({"matcap", "normals", "flat"}));
  cmd->add_option("--camera", a->camera, "orbit yaw,pitch[,distance] in degrees (default: auto-framed 30,20)");
  cmd->add_flag("--mesh", a->mesh_lines, "draw the base mesh as thin grey lines");
  cmd->add_flag("--wireframe", a->wireframe, "draw the tessellation wireframe over the shading");
  cmd->add_flag("--ellipsoids", a->ellipsoids, "draw the covariance ellipsoids");
  cmd->add_option("--sigma", a->sigma, "ellipsoid scale in standard deviations (k-sigma)")->check(CLI::Range(0.01f, 100.0f));
  cmd->add_option("--background", a->background, "background colour r,g,b in [0,1]");
  cmd->add_option("--aov", a->aovs, "world-space float buffers: position=FILE.exr, normal=FILE.exr");
  cmd->add_option("--reference", a->reference, "draw the CPU reference subdivision at level N instead of the patches")->check(CLI::Range(0, 7));
  cmd->callback([a] { render(*a); });
}

}  // namespace gps
