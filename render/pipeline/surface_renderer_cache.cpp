// The surface renderer's use of the surface cache (render/cache/surface_cache.h): the key of a frame,
// whether it draws stored triangles, refreshes them or captures them again, and the patches'
// triangle counts the cache places blocks by.
#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/pipeline/surface_renderer.h"

namespace gps {

void SurfaceRenderer::draw_cache(bool grid) {
  const bool counted = cached_statistics_ && cached_statistics_->begin();
  cache_.draw(grid);
  if (counted) cached_statistics_->end();
}

SurfaceCache::Key SurfaceRenderer::cache_key(const DrawOptions& o) const {
  SurfaceCache::Key key;
  key.points = points_generation_;
  key.pixels = std::max(o.pixels, 0.0f);
  key.level = key.pixels > 0.0f ? 0.0f : uniform_level(o);
  key.mismatched_edge_levels = o.diagnostics.mismatched_edge_levels;
  return key;
}

// The storage buffers bound; the target not yet (none of this draws).
bool SurfaceRenderer::prepare_cache(const Camera& camera, const DrawOptions& o, float aspect, int width, int height) {
  const SurfaceCache::Key key = cache_key(o);
  const glm::mat4 view_projection = frame_view_projection(camera, aspect, frame_);
  const glm::vec2 viewport{float(width), float(height)};
  if (cache_.matches(key, view_projection, viewport)) {
    cache_.settle();
    return true;
  }
  // An edit: its patches, under the capture's camera.
  if (!cache_.can_refresh_to(key, view_projection, viewport)) return false;
  const ShaderProgram& capture = patches_.program(shape(), PatchOutput::capture);
  capture.use();
  set_frame_uniforms(capture, camera, o, aspect, width, height, frame_);
  capture.set("u_view_projection", cache_.captured_view_projection());
  capture.set("u_viewport", cache_.captured_viewport());
  const auto draw_patches = [&](int first, int count) {
    patches_.draw(shape(), capture, o, n_patches(), first, count);
  };
  const auto evaluate_welded = [&](const std::vector<StoredVertexEvaluation::Block>& blocks, unsigned welded_counts) {
    stored_evaluation_.run(tables().plans, blocks, welded_counts, group_limit_);
  };
  const auto levels_changed = [&](const std::vector<StoredPatchLevels::Block>& blocks) {
    const ShaderProgram& check = stored_levels_.program(shape());
    set_level_uniforms(check, cache_.captured_view_projection(), cache_.captured_viewport(), o);
    return stored_levels_.changed(shape(), blocks, group_limit_);
  };
  const auto patch_triangles = [&](const std::vector<int>& patches) {
    return triangle_counts(cache_.captured_view_projection(), cache_.captured_viewport(), o, patches);
  };
  if (!cache_.refresh(key, draw_patches, evaluate_welded, levels_changed, patch_triangles)) return false;
  if (draws_grid(o)) cache_.copy_back_evaluated();
  return true;
}

// Captures the patches' triangles (the storage buffers and the frame's target bound). It draws the
// frame as it goes (the shaded program under transform feedback, rasteriser on), but where a
// geometry stage draws the triangle wireframe: transform feedback would store its output.
SurfaceRenderer::CacheFrame SurfaceRenderer::capture_cache(const Camera& camera, const DrawOptions& o, float aspect,
                                                           int width, int height) {
  const SurfaceCache::Key key = cache_key(o);
  const glm::mat4 view_projection = frame_view_projection(camera, aspect, frame_);
  const glm::vec2 viewport{float(width), float(height)};
  // Buffer size: uniform level L generates about 2·L² triangles per quad patch, 2·⌈L/2⌉² per
  // half-size one (shaders/patch_tesc.glsl), L² per triangle patch; adaptive levels as many as last
  // time, or where nothing is stored, as many as a draw counts (a fixed bound such as 128 a patch
  // would take gigabytes for a large mesh that draws far fewer). A full buffer grows and captures again.
  const long long level = (long long)std::ceil(key.level), patches = n_patches();
  long long estimate = 64;
  if (key.pixels > 0.0f) {
    if (cache_.triangles() > 0) {
      estimate += cache_.triangles() * 5 / 4;
    } else {
      estimate += patches_.count_triangles(shape(), camera, o, width, height, patches) * 9 / 8;
    }
  } else if (shape() == PatchShape::triangle) {
    estimate += patches * level * level * 5 / 4;
  } else {
    if (half_size_patches_ < 0) {
      half_size_patches_ = 0;
      for (int p = 0; p < n_patches(); ++p) half_size_patches_ += half_size_patch(tables().plans, p);
    }
    const long long halves = half_size_patches_, half_level = (level + 1) / 2;
    estimate += ((patches - halves) * 2 * level * level + halves * 2 * half_level * half_level) * 5 / 4;
  }
  // Each patch's triangles from its levels, where they agreed with the queries before: the blocks
  // are then captured in one draw (SurfaceCache::capture).
  const std::vector<int> patch_counts =
      cache_.counts_captures() ? all_triangle_counts(view_projection, viewport, o) : std::vector<int>{};
  const bool triangle_wire = o.wireframe && shape() == PatchShape::triangle;
  const ShaderProgram& program =
      patches_.program(shape(), triangle_wire ? PatchOutput::capture : PatchOutput::shaded_capture);
  set_frame_uniforms(program, camera, o, aspect, width, height, frame_);
  program.use();
  const auto draw = [&](int first, int count) { patches_.draw(shape(), program, o, n_patches(), first, count); };
  if (!cache_.capture(key, view_projection, viewport, n_patches(), estimate, draw, !triangle_wire,
                      patch_counts.empty() ? nullptr : &patch_counts))
    return CacheFrame::live;
  if (key.pixels > 0.0f) {  // the levels an edit's refresh checks
    const ShaderProgram& record = stored_levels_.program(shape());
    set_level_uniforms(record, view_projection, viewport, o);
    stored_levels_.record(shape(), n_patches(), group_limit_);
  }
  // The counts a change of topology's refresh may split blocks by, checked against the capture's
  // queries (a counted capture checked them all by its one).
  if (!cache_.last_capture_counted())
    cache_.check_patch_triangles(triangle_counts(view_projection, viewport, o, cache_.checked_patches()));
  return triangle_wire ? CacheFrame::stored : CacheFrame::drawn;  // the triangle wireframe: drawn from the cache
}

std::vector<int> SurfaceRenderer::patch_triangle_counts(const Camera& camera, const DrawOptions& o, int width,
                                                        int height) {
  buffers_.bind();
  return all_triangle_counts(frame_view_projection(camera, float(width) / float(height), frame_),
                             glm::vec2(float(width), float(height)), o);
}

std::vector<int> SurfaceRenderer::all_triangle_counts(const glm::mat4& view_projection, glm::vec2 viewport,
                                                      const DrawOptions& o) {
  std::vector<int> patches(static_cast<size_t>(n_patches()));
  std::iota(patches.begin(), patches.end(), 0);
  return triangle_counts(view_projection, viewport, o, patches);
}

std::vector<int> SurfaceRenderer::triangle_counts(const glm::mat4& view_projection, glm::vec2 viewport,
                                                  const DrawOptions& o, const std::vector<int>& patches) {
  set_level_uniforms(triangle_counts_.program(shape()), view_projection, viewport, o);
  return triangle_counts_.count(shape(), patches, group_limit_);
}

}  // namespace gps
