// gpsurf render IN -o OUT.png: a headless render of the GPS limit surface (OSMesa, no display).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <type_traits>

#include "app/cli_checks.h"
#include "app/commands.h"
#include "app/gl_commands.h"
#include "app/plan_arguments.h"
#include "app/naming_input.h"
#include "app/repair_arguments.h"
#include "core/support/error.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "core/modelling/operation_list.h"
#include "core/io/json_text.h"
#include "core/io/number_text.h"
#include "core/support/quoted_text.h"
#include "core/io/text_file.h"
#include "render/gl/render_target.h"
#include "render/comparison/exact_triangles.h"
#include "render/gl/gl_context.h"
#include "render/image/image_io.h"
#include "render/image/matcap.h"
#include "render/image/matcap_file.h"
#include "render/image/non_finite_pixels.h"
#include "render/comparison/reference_triangles.h"
#include "render/pipeline/render_framing.h"
#include "render/pipeline/surface_renderer.h"

namespace gps {

namespace {

// The largest connected part's bounding-box diagonal over the whole mesh's: framed on the whole, a
// part is that share of the image across.
double largest_part_share(const CovarianceMesh& mesh) {
  std::vector<int> parent(mesh.n_vertices());
  for (size_t v = 0; v < parent.size(); ++v) parent[v] = int(v);
  const auto root = [&](int v) {
    while (parent[size_t(v)] != v) v = parent[size_t(v)] = parent[size_t(parent[size_t(v)])];
    return v;
  };
  for (size_t f = 0; f < mesh.n_faces(); ++f)
    for (const int v : mesh.face(f)) parent[size_t(root(v))] = root(mesh.face(f)[0]);
  std::vector<Vec3> lo(mesh.n_vertices(), Vec3::Constant(HUGE_VAL)), hi(mesh.n_vertices(), Vec3::Constant(-HUGE_VAL));
  for (size_t v = 0; v < mesh.n_vertices(); ++v) {
    const int r = root(int(v));
    lo[size_t(r)] = lo[size_t(r)].cwiseMin(mesh.mean(v));
    hi[size_t(r)] = hi[size_t(r)].cwiseMax(mesh.mean(v));
  }
  double largest = 0;
  for (size_t v = 0; v < mesh.n_vertices(); ++v)
    if (root(int(v)) == int(v)) largest = std::max(largest, (hi[v] - lo[v]).norm());
  const double whole = bounding_box_diagonal(mesh);
  return whole > 0 ? largest / whole : 1.0;
}

// How many pixels across the mesh's bounding box shows in the width × height image of `camera`.
double pixels_across(const CovarianceMesh& mesh, const Camera& camera, int width, int height) {
  Vec3 lo, hi;
  bounding_box(mesh, lo, hi);
  const glm::dmat4 view_projection = camera.view_projection_double(float(width) / float(height));
  glm::dvec2 min(HUGE_VAL), max(-HUGE_VAL);
  for (int c = 0; c < 8; ++c) {
    const glm::dvec4 p =
        view_projection * glm::dvec4(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z(), 1.0);
    const glm::dvec2 pixel = (glm::dvec2(p) / p.w * 0.5 + 0.5) * glm::dvec2(width, height);
    min = glm::min(min, pixel), max = glm::max(max, pixel);
  }
  return std::max(max.x - min.x, max.y - min.y);
}

struct RenderArgs {
  std::string input, output, size = "800x600", matcap = "clay", mode = "matcap", camera, background = "1,1,1", up = "y";
  std::vector<std::string> aovs;
  int level = 0, reference = -1;  // level 0: adaptive
  PlanArguments plans;
  RepairArguments repair;
  float pixels = 0;  // 0: default_adaptive_pixels() of the output size
  std::string context = "auto";
  bool mesh_lines = false, wireframe = false, ellipsoids = false, no_cache = false, exact = false;
  float sigma = 1.0f;
};

std::vector<float> parse_floats(const std::string& text, const char* what, size_t min_count, size_t max_count) {
  std::vector<float> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    double value = 0;
    if (!parse_number(item, value).empty() || !std::isfinite(value))
      throw usage_error(std::string(what) + ": " + quoted_token(text) + " is not a comma-separated list of numbers");
    if (std::abs(value) > std::numeric_limits<float>::max())
      throw usage_error(std::string(what) + ": " + quoted_token(item) + " is beyond the range of a float");
    values.push_back(float(value));
  }
  if (values.size() < min_count || values.size() > max_count)
    throw usage_error(std::string(what) + ": expected " + std::to_string(min_count) +
                      (max_count > min_count ? " to " + std::to_string(max_count) : std::string()) + " numbers, got " +
                      quoted_token(text));
  return values;
}

// One render with the given renderer (its context current): mesh, options, outputs.
void render_one(SurfaceRenderer& renderer, const std::string& description, const RenderArgs& a,
                const CovarianceMesh& mesh) {
  const auto [width, height] = parse_pixel_size(a.size, "--size", RenderTarget::kLargestSide);
  std::string position_aov, normal_aov;
  // Each file written once: an AOV given twice, or two outputs at one path, would overwrite one another.
  std::vector<std::filesystem::path> written = {std::filesystem::absolute(a.output).lexically_normal()};
  for (const auto& aov : a.aovs) {
    const auto eq = aov.find('=');
    const std::string kind = aov.substr(0, eq), file = eq == std::string::npos ? "" : aov.substr(eq + 1);
    if (file.empty() || (kind != "position" && kind != "normal"))
      throw usage_error("--aov: expected position=FILE.exr or normal=FILE.exr, got " + quoted_token(aov));
    std::string& path = kind == "position" ? position_aov : normal_aov;
    if (!path.empty()) throw usage_error("--aov: " + kind + " is given twice");
    path = file;
    const std::filesystem::path normal = std::filesystem::absolute(file).lexically_normal();
    if (std::find(written.begin(), written.end(), normal) != written.end())
      throw usage_error("--aov: " + quoted_token(file) + " is written twice (as the image or another AOV)");
    written.push_back(normal);
  }
  const auto bg = parse_floats(a.background, "--background", 3, 3);
  for (const float channel : bg)
    if (!(channel >= 0.0f && channel <= 1.0f))
      throw usage_error("--background: each of red, green and blue is from 0 to 1, got " + quoted_token(a.background));
  const Image matcap = load_matcap(a.matcap);
  // A refusal (a face or valence the plans do not take, the storage limit) names the mesh it is about.
  naming_mesh_input(a.input, a.repair.import_options().repair, [&] { renderer.set_mesh(mesh, a.plans.options()); });
  renderer.set_matcap(matcap);
  DrawOptions o;
  set_render_tessellation(o, a.level, a.pixels, width, height);
  o.mode = a.mode == "normals" ? ShadingMode::normals : a.mode == "flat" ? ShadingMode::flat : ShadingMode::matcap;
  o.mesh_lines = a.mesh_lines;
  o.wireframe = a.wireframe;
  o.surface_cache = false;  // one image: captured triangles would never be drawn again
  o.ellipsoids = a.ellipsoids;
  o.sigma_scale = a.sigma;
  o.background = {bg[0], bg[1], bg[2]};
  const std::vector<float> yaw_pitch_distance =
      a.camera.empty() ? std::vector<float>{} : parse_floats(a.camera, "--camera", 2, 3);
  if (yaw_pitch_distance.size() > 2 && !(yaw_pitch_distance[2] > 0.0f))
    throw usage_error("--camera: the distance must be positive (in the mesh's units), got " + quoted_token(a.camera));
  const int up_axis = up_axis_named(a.up);
  // The image's size by value: clang's lambdas do not capture structured bindings.
  const Camera camera = naming_mesh_input(a.input, a.repair.import_options().repair, [&, w = width, h = height] {
    return render_camera(renderer, mesh, yaw_pitch_distance, up_axis, o, w, h);
  });
  if (a.reference >= 1 && a.reference <= 6 && scheme_for(mesh.topology(), a.plans.options()) == Scheme::catmull_clark) {
    // In the patches' own triangles at level 2^N: `diff` against the patches drawn at that level
    // then shows the two surfaces' values alone, not two draws' rounding (render/comparison/reference_triangles.h).
    DrawOptions at_level = o;
    at_level.level = float(1 << a.reference), at_level.pixels = 0;
    renderer.set_triangles(reference_in_patch_triangles(renderer, mesh, camera, at_level, width, height, a.reference));
  } else if (a.reference >= 0) {
    renderer.set_triangles(reference_triangles(mesh, a.reference, a.plans.options()));
  }
  if (a.exact) renderer.set_triangles(exact_triangles(renderer, mesh, camera, o, width, height));
  o.static_triangles = a.reference >= 0 || a.exact;
  RenderTarget target(width, height);
  renderer.draw(target, camera, o);
  // A frame the float evaluation could not represent is an error, not an image.
  const Image position = target.read(1), normal = target.read(2);
  if (const long long bad = count_non_finite_pixels(position, normal); bad > 0)
    throw Error(a.input + ": the GPU's evaluation is not finite at " + std::to_string(bad) +
                " pixels; nothing written");
  // Framed on the surface, an image without it means the evaluation lost it (Gaussians too thin
  // for the GPU's precision: render/gl/point_precision.h), not a view that looks away.
  // From a distance given, an image without it shows that camera's view of nothing: refused as well,
  // with the mesh's size to place the camera by.
  if (count_covered_pixels(normal) == 0) {
    if (yaw_pitch_distance.size() < 3 && a.ellipsoids && pixels_across(mesh, camera, width, height) < 2.0) {
      std::ostringstream sigma;
      sigma << a.sigma;
      throw Error(a.input + ": the surface covers no pixel of the image framed on it: the ellipsoids at sigma " +
                  sigma.str() + " frame an image in which it is under 2 pixels across (use a smaller sigma or a " +
                  "larger size); nothing written");
    }
    if (yaw_pitch_distance.size() < 3) {
      // An image a pixel or two across, or parts far apart, each under a pixel of the image framed on
      // them all, cover no pixel's centre.
      const double share = largest_part_share(mesh), across = share * double(std::min(width, height));
      if (across < 2.0) {
        std::ostringstream pixels;
        pixels.precision(2);
        pixels << across;
        if (share == 1.0)
          throw Error(a.input + ": the surface covers no pixel of the image framed on it: at " + a.size +
                      " it is under 2 pixels across and falls between the pixels' centres (use a larger --size); " +
                      "nothing written");
        throw Error(a.input + ": the surface covers no pixel of the image framed on it: its parts lie so far " +
                    "apart that the largest is " + pixels.str() + " pixels across (render the parts apart, or " +
                    "a larger --size); nothing written");
      }
      throw Error(a.input +
                  ": the surface covers no pixel of the image framed on it (Gaussians too thin for the "
                  "GPU's evaluation?); nothing written");
    }
    std::ostringstream diagonal;
    diagonal << bounding_box_diagonal(mesh);
    // A camera close to the mesh or inside it sees only up to 100 times its distance (the far plane,
    // view/camera.h): the mesh beyond that is cut away.
    const Vec3 eye(camera.eye_double().x, camera.eye_double().y, camera.eye_double().z);
    double farthest = 0;
    for (size_t v = 0; v < mesh.n_vertices(); ++v) farthest = std::max(farthest, (mesh.mean(v) - eye).norm());
    if (farthest > 100.0 * double(camera.distance)) {
      std::ostringstream reach;
      reach << 100.0 * double(camera.distance);
      throw Error(a.input + ": the surface covers no pixel of the image from the camera " + quoted_token(a.camera) +
                  ": so near the mesh (whose bounding box has a diagonal of " + diagonal.str() +
                  ") the view reaches only " + reach.str() + " beyond the camera, 100 times its distance; " +
                  "give a larger distance; nothing written");
    }
    throw Error(a.input + ": the surface covers no pixel of the image from the camera " + quoted_token(a.camera) +
                " (its distance is in the mesh's units, whose bounding box has a diagonal of " + diagonal.str() +
                "; leave the distance out to frame the surface); nothing written");
  }
  Image color = target.read(0);
  write_image(a.output, color);
  if (!position_aov.empty()) write_image(position_aov, position, kPositionChannels);
  if (!normal_aov.empty()) write_image(normal_aov, normal, kNormalChannels);
  std::ostringstream tessellation;
  if (a.reference >= 0)
    tessellation << "reference level " << a.reference;
  else if (o.pixels > 0)
    tessellation << "adaptive " << o.pixels << " px";
  else
    tessellation << "level " << a.level;
  if (a.exact) tessellation << ", exact evaluator";
  std::cout << "wrote " << a.output << " (" << width << "x" << height << ", " << renderer.tables().plans.n_patches()
            << " patches, " << tessellation.str() << ", " << description << ")\n";
}

ContextKind context_kind(const std::string& name) {
  return name == "egl" ? ContextKind::egl : name == "osmesa" ? ContextKind::osmesa : ContextKind::automatic;
}

void render(const RenderArgs& a) {
  load_matcap(a.matcap);  // before any GL work: a bad name or size is a usage error
  parse_pixel_size(a.size, "--size", RenderTarget::kLargestSide);
  const CovarianceMesh mesh = read_mesh_repairing(a.input, a.repair);
  const auto context = create_offscreen_context(context_kind(a.context));
  SurfaceRenderer renderer;
  render_one(renderer, context->description(), a, mesh);
}

// --script FILE.json: {"renders": [{"mesh": FILE or "sample:NAME", "output": FILE.png, "size": "WxH",
// "level": L, "pixels": P, "depth": D, "approximate": true|false, "scheme": "auto"|"loop"|"catmull-clark", "loop_beta":
// "loop"|"warren", "matcap": M, "mode": M, "camera": "yaw,pitch[,distance]", "up": "x"|"y"|"z", "mesh_lines": bool,
// "wireframe": bool, "ellipsoids": bool, "sigma": k, "background": "r,g,b", "aov": ["position=FILE.exr", ...],
// "reference": N, "exact": true|false, "ops": [modelling operations, as gpsurf edit --ops], "edits": [{"vertex": i,
// "mean": [x,y,z], "covariance": [xx,xy,xz,yy,yz,zz], "scale": s}]}, ...]} All renders share one process and one GL
// context.
// A script's number at `key` of `object`, checked as the type it becomes; the message names the key.
long long script_integer(const nlohmann::json& object, const char* key, long long lo, long long hi) {
  try {
    return json_integer(object.at(key), lo, hi);
  } catch (const Error& e) {
    throw usage_error(std::string(key) + " " + e.what());
  }
}
double script_number(const nlohmann::json& object, const char* key, double lo, double hi) {
  try {
    const double value = json_number(object.at(key));
    if (value < lo || value > hi)
      throw usage_error("must be from " + json_shown(lo) + " to " + json_shown(hi) + ", got " +
                        json_shown(object.at(key)));
    return value;
  } catch (const Error& e) {
    throw usage_error(std::string(key) + " " + e.what());
  }
}
// The value at `key` of a job as the type of `fallback` (absent: `fallback`); another type is refused
// naming the key, as the numbers are.
template <class T>
T script_value(const nlohmann::json& job, const char* key, const T& fallback) {
  if (!job.contains(key)) return fallback;
  try {
    return job.at(key).get<T>();
  } catch (const nlohmann::json::type_error&) {
    const char* kind = std::is_same_v<T, bool>          ? "true or false"
                       : std::is_same_v<T, std::string> ? "a string"
                                                        : "a list of strings";
    throw usage_error(std::string(key) + " must be " + kind + ", got " + json_shown(job.at(key)));
  }
}
// The numbers at `key` of an edit, exactly `count` of them.
std::vector<double> script_numbers(const nlohmann::json& edit, const char* key, size_t count) {
  const nlohmann::json& list = edit.at(key);
  if (!list.is_array() || list.size() != count)
    throw usage_error(std::string(key) + " needs " + std::to_string(count) + " numbers");
  std::vector<double> out;
  for (size_t i = 0; i < count; ++i) {
    try {
      out.push_back(json_number(list[i]));
    } catch (const Error& e) {
      throw usage_error(std::string(key) + "[" + std::to_string(i) + "] " + e.what());
    }
  }
  return out;
}

// The keys a render script's job may have (run_script).
constexpr const char* kScriptKeys[] = {
    "mesh",   "output",     "size",   "level",     "pixels", "depth", "approximate", "scheme",    "loop_beta",
    "repair", "weld",       "matcap", "mode",      "camera", "up",    "mesh_lines",  "wireframe", "ellipsoids",
    "sigma",  "background", "aov",    "reference", "exact",  "ops",   "edits"};

void run_script(const std::string& path, const std::string& context_name) {
  const std::string text = read_text_file(path);  // a file that cannot be read: exit 1, as for a mesh
  nlohmann::json script;
  try {
    script = parse_json(text, path);
  } catch (const Error& e) {
    throw usage_error(e.what());
  }
  if (!script.is_object() || !script.contains("renders") || !script["renders"].is_array())
    throw usage_error(path + ": expected {\"renders\": [ ... ]}");
  const auto context = create_offscreen_context(context_kind(context_name));
  SurfaceRenderer renderer;
  int index = 0;
  for (const auto& job : script["renders"]) {
    const std::string where = path + ": render " + std::to_string(index++);
    try {
      RenderArgs a;
      if (!job.is_object()) throw usage_error("expected an object");
      for (const auto& [key, value] : job.items())
        if (std::find(std::begin(kScriptKeys), std::end(kScriptKeys), key) == std::end(kScriptKeys))
          throw usage_error("unknown key " + quoted_token(key));
      if (job.contains("camera") && job["camera"] == "")
        throw usage_error("camera: give \"yaw,pitch[,distance]\", got \"\"");
      a.input = script_value(job, "mesh", std::string());
      if (a.input.empty()) throw usage_error("mesh is missing");
      a.output = script_value(job, "output", std::string());
      if (a.output.empty()) throw usage_error("output is missing");
      a.size = script_value(job, "size", a.size);
      if (job.contains("level")) a.level = int(script_integer(job, "level", 1, 64));
      if (job.contains("pixels")) a.pixels = float(script_number(job, "pixels", 0.5, 1000));
      if (job.contains("depth")) a.plans.depth = int(script_integer(job, "depth", 0, 8));
      a.plans.approximate = script_value(job, "approximate", a.plans.approximate);
      a.plans.scheme = script_value(job, "scheme", a.plans.scheme);
      a.plans.loop_beta = script_value(job, "loop_beta", a.plans.loop_beta);
      a.plans.options();  // checks the names and the depth
      a.repair.repair = script_value(job, "repair", a.repair.repair);
      if (job.contains("weld")) a.repair.weld = script_number(job, "weld", 0, 1e100);
      a.matcap = script_value(job, "matcap", a.matcap);
      a.mode = script_value(job, "mode", a.mode);
      a.camera = script_value(job, "camera", a.camera);
      a.up = script_value(job, "up", a.up);
      a.mesh_lines = script_value(job, "mesh_lines", a.mesh_lines);
      a.wireframe = script_value(job, "wireframe", a.wireframe);
      a.ellipsoids = script_value(job, "ellipsoids", a.ellipsoids);
      if (job.contains("sigma")) a.sigma = float(script_number(job, "sigma", 0.01, 100));
      a.background = script_value(job, "background", a.background);
      a.aovs = script_value(job, "aov", a.aovs);
      if (job.contains("reference")) a.reference = int(script_integer(job, "reference", 0, 7));
      a.exact = script_value(job, "exact", a.exact);
      if (a.exact && a.reference >= 0) throw usage_error("exact and reference exclude each other");
      if (a.mode != "matcap" && a.mode != "normals" && a.mode != "flat")
        throw usage_error("mode must be matcap, normals or flat");
      CovarianceMesh mesh =
          a.input.rfind("sample:", 0) == 0 ? make_sample(a.input.substr(7)) : read_mesh_repairing(a.input, a.repair);
      if (job.contains("ops")) mesh = OperationList::parse(job["ops"].dump(), "").apply(mesh).mesh;
      const nlohmann::json edits = job.value("edits", nlohmann::json::array());
      if (!edits.is_array()) throw usage_error("edits: give a list of {\"vertex\": i, ...}");
      for (size_t e = 0; e < edits.size(); ++e) {
        const nlohmann::json& edit = edits[e];
        const std::string named = "edits[" + std::to_string(e) + "]";
        if (!edit.is_object()) throw usage_error(named + ": give {\"vertex\": i, ...}");
        const long long v = script_integer(edit, "vertex", 0, std::numeric_limits<int>::max());
        if (size_t(v) >= mesh.n_vertices())
          throw Error(named + ": vertex " + std::to_string(v) + " is not in the mesh (" +
                      std::to_string(mesh.n_vertices()) + " vertices)");  // as gpsurf edit says it, exit 1
        if (edit.contains("mean")) {
          const std::vector<double> m = script_numbers(edit, "mean", 3);
          mesh.set_mean(size_t(v), Vec3(m[0], m[1], m[2]));
        }
        if (edit.contains("covariance")) {
          const std::vector<double> c = script_numbers(edit, "covariance", 6);
          Mat3 m;
          m << c[0], c[1], c[2], c[1], c[3], c[4], c[2], c[4], c[5];
          mesh.set_covariance(size_t(v), m);
        }
        if (edit.contains("scale"))
          mesh.set_covariance(size_t(v), mesh.covariance(size_t(v)) * script_number(edit, "scale", 0, 1e100));
        // The limits every mesh keeps (core/mesh/covariance_mesh.h), as gpsurf edit's "set" has them.
        std::string why = position_problem(mesh.mean(size_t(v)));
        if (why.empty()) why = covariance_problem(mesh.covariance(size_t(v)));
        if (!why.empty()) throw usage_error(named + ": vertex " + std::to_string(v) + " " + why);
      }
      render_one(renderer, context->description(), a, mesh);
    } catch (const nlohmann::json::exception& e) {
      throw usage_error(where + ": " + json_error_words(e));
    } catch (const Error& e) {
      throw Error(where + ": " + e.what(), e.kind());
    }
  }
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  auto* cmd = app.add_subcommand("render", gl_command_summary("render"));
  auto script = std::make_shared<std::string>();
  auto* input = cmd->add_option("input", a->input, "input mesh");
  auto* output = cmd->add_option("-o,--output", a->output, "output image (.png)");
  cmd->add_option("--script", *script, "run the renders listed in a JSON file, in one process and one context")
      ->excludes(input)
      ->excludes(output);
  cmd->add_option("--size", a->size, "image size WxH");
  auto* level = cmd->add_option("--level", a->level, "uniform tessellation level (default: adaptive, see --pixels)")
                    ->transform(integer_in(1, 64));
  cmd->add_option(
         "--pixels", a->pixels,
         "adaptive tessellation: target edge length in pixels (default: 1% of the smaller image side, at least 4)")
      ->check(number_in(0.5, 1000))
      ->excludes(level);
  add_plan_arguments(cmd, a->plans);
  add_repair_arguments(cmd, a->repair);
  cmd->add_option(
      "--matcap", a->matcap, "built-in MatCap (" + [] {
        std::string s;
        for (const auto& n : builtin_matcap_names()) s += (s.empty() ? "" : ", ") + n;
        return s;
      }() + ") or an image file");
  cmd->add_option("--mode", a->mode, "shading")->check(CLI::IsMember({"matcap", "normals", "flat"}));
  auto* camera =
      cmd->add_option("--camera", a->camera, "orbit yaw,pitch[,distance] in degrees (default: auto-framed 30,20)");
  cmd->add_option("--up", a->up, "the world axis drawn upward (z for most scans; default y)")
      ->check(CLI::IsMember({"x", "y", "z"}));
  cmd->add_flag("--mesh", a->mesh_lines, "draw the base mesh as thin grey lines");
  cmd->add_flag("--wireframe", a->wireframe, "draw the tessellation wireframe over the shading");
  cmd->add_flag("--no-cache", a->no_cache,
                "no effect, kept for old scripts: a render draws its one image through the tessellation pipeline, "
                "without the surface cache");
  cmd->add_option("--context", a->context, "GL context: auto (EGL on a GPU device, else OSMesa), osmesa, egl")
      ->check(CLI::IsMember({"auto", "osmesa", "egl"}));
  cmd->add_flag("--ellipsoids", a->ellipsoids, "draw the covariance ellipsoids");
  cmd->add_option("--sigma", a->sigma, "ellipsoid scale in standard deviations (k-sigma)")->check(number_in(0.01, 100));
  cmd->add_option("--background", a->background, "background colour r,g,b in [0,1]");
  cmd->add_option("--aov", a->aovs, "world-space float buffers: position=FILE.exr, normal=FILE.exr");
  auto* reference =
      cmd->add_option("--reference", a->reference,
                      "draw the CPU reference subdivision at level N instead of the patches: under Catmull-Clark "
                      "(N = 1..6) in the patches' own triangles at --level 2^N, so that diff against them shows the "
                      "surfaces alone; under Loop, whose triangles no reference level has, see --exact")
          ->transform(integer_in(0, 7));
  cmd->add_flag(
         "--exact", a->exact,
         "draw the patches' own triangles with the CPU's exact values at their vertices (double): diff against a "
         "render of the patches shows the GPU's error alone, at any level and under either scheme")
      ->excludes(reference);
  cmd->callback([a, script, camera] {
    if (camera->count() > 0 && a->camera.empty()) throw usage_error("--camera: give yaw,pitch[,distance], got ''");
    if (!script->empty()) return run_script(*script, a->context);
    if (a->input.empty() || a->output.empty())
      throw usage_error("render: give an input mesh and -o OUTPUT.png (or --script FILE.json)");
    render(*a);
  });
}

}  // namespace gps
