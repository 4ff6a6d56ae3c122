#include "bench/frame_figures.h"

#include <cmath>

#include "bench/edit_scene.h"
#include "core/mesh/dual_map.h"
#include "core/plans/stencil_table.h"
#include "core/evaluation/tessellator.h"
#include "render/gl/frame_timer.h"
#include "render/gl/render_target.h"

namespace gps {

nlohmann::json frame_figures(const std::string& name, int faces, const PlanOptions& options, int size,
                             const std::vector<int>& levels, float adaptive_pixels) {
  EditScene scene(name, faces, options);  // its edits scale a covariance by 1.1 and the next one back
  SurfaceRenderer& renderer = scene.renderer();
  const CovarianceMesh& mesh = scene.mesh();
  const Camera& camera = scene.camera();
  RenderTarget target(size, size);
  const FrameTiming compute = time_gl_work([&] { renderer.recompute_all(); }, 5);
  const std::vector<Dual> points = apply_stencils(renderer.tables().stencils, base_points(mesh));
  const std::vector<int> edited = scene.middle_vertices(1);
  std::vector<DrawOptions> settings;
  for (const int level : levels) {
    settings.emplace_back();
    settings.back().level = float(level);
  }
  if (adaptive_pixels > 0.0f) {
    settings.emplace_back();
    settings.back().pixels = adaptive_pixels;
  }
  nlohmann::json rows = nlohmann::json::array();
  for (DrawOptions o : settings) {
    DrawOptions live = o, cached = o;
    live.surface_cache = false;
    cached.surface_cache = true;
    renderer.draw(target, camera, cached);  // fills the cache, whose triangles the floor draws
    const size_t cache_bytes = renderer.surface_cache_bytes();
    const bool cache_held = renderer.surface_cache().has_stored_triangles();
    // The floor draws exactly the cached triangles; past the cache's limit, those of the CPU
    // tessellation (uniform levels; adaptive ones then have no floor).
    const TriangleMesh triangles = cache_held        ? renderer.surface_cache().stored_triangles()
                                   : o.pixels > 0.0f ? TriangleMesh{}
                                                     : tessellate(renderer.tables().plans, points, int(o.level));
    renderer.set_triangles(triangles);
    DrawOptions static_options = o;
    static_options.static_triangles = true;
    // Live, cached and floor frames side by side (the Google Benchmarks' method: warm-up, steady
    // state, medians), so that the ratios compare frames of the same moment.
    const auto frames = time_gl_work_interleaved(
        {[&] { renderer.draw(target, camera, live); }, [&] { renderer.draw(target, camera, cached); },
         [&] { renderer.draw(target, camera, static_options); }},
        5, 1.0);
    const FrameTiming &patches = frames[0], &cached_frame = frames[1], &floor = frames[2];
    const FrameTiming edit = time_gl_work(
        [&] {
          scene.edit(edited);
          renderer.draw(target, camera, cached);
        },
        5);
    const double n = double(triangles.triangles.size());
    const double floor_ms = n > 0 ? floor.wall_ms : std::nan("");
    rows.push_back({{"mesh", name + (faces ? "/" + std::to_string(faces) : "")},
                    {"faces", mesh.n_faces()},
                    {"patches", renderer.tables().plans.n_patches()},
                    {"level", o.pixels > 0.0f ? 0 : int(o.level)},
                    {"adaptive_pixels", o.pixels},
                    {"triangles", n},
                    {"compute_gpu_ms", compute.gpu_ms},
                    {"draw_gpu_ms", patches.gpu_ms},
                    {"frame_ms", patches.wall_ms},
                    {"triangles_per_second", n / (patches.wall_ms * 1e-3)},
                    {"static_buffer_frame_ms", floor_ms},
                    {"ratio_to_static_buffer", patches.wall_ms / floor_ms},
                    {"cached_frame_ms", cached_frame.wall_ms},
                    {"cached_ratio_to_static_buffer", cached_frame.wall_ms / floor_ms},
                    {"edit_frame_ms", edit.wall_ms},
                    {"edit_ratio_to_static_buffer", edit.wall_ms / floor_ms},
                    {"cache_held", cache_held},
                    {"cache_buffer_bytes", cache_bytes},
                    {"pipeline_buffer_bytes", renderer.buffer_bytes()},
                    {"static_buffer_bytes", triangles.positions.size() * 24 + triangles.triangles.size() * 12}});
  }
  return rows;
}

}  // namespace gps
