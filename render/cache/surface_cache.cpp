#include "render/cache/surface_cache.h"

#include <glad/gl.h>

#include <algorithm>
#include <glm/gtc/matrix_access.hpp>
#include <iterator>

#include "render/gl/device_memory.h"
#include "render/gl/gl_context.h"

namespace gps {

SurfaceCache::SurfaceCache()
    : weld_mode_(software_renderer() ? Weld::when_settled : Weld::at_capture),
      limit_bytes_(std::clamp(device_memory_bytes() / kDeviceMemoryShare, kLeastLimitBytes, kMostLimitBytes)) {
  glVertexArrayVertexBuffer(vao_, 0, buffer_, 0, kCapturedVertexBytes);
  glVertexArrayVertexBuffer(welded_vao_, 0, welded_, 0, kWeldedVertexBytes);
  glVertexArrayElementBuffer(welded_vao_, indices_);
  for (const GLuint vao : {vao_.get(), welded_vao_.get()})
    for (GLuint a = 0; a < (vao == vao_ ? 3u : 2u); ++a) {  // welded: no grid
      glEnableVertexArrayAttrib(vao, a);
      glVertexArrayAttribFormat(vao, a, 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
      glVertexArrayAttribBinding(vao, a, 0);
    }
  check_gl_errors("creating the surface cache");
}

void SurfaceCache::set_cage(const CovarianceMesh& mesh, const FramedGaussians& gaussians, bool follow) {
  const size_t n = gaussians.n_vertices();
  cage_positions_.resize(n);
#pragma omp parallel for schedule(static) if (n >= size_t(kParallelFaces))
  for (size_t i = 0; i < n; ++i) {
    const Vec3& m = gaussians.mean(i);
    cage_positions_[i] = glm::vec3(float(m.x()), float(m.y()), float(m.z()));
  }
  cage_shape_ = mesh.shape();
  if (follow) return;
  stored_ = false;
  tracked_points_ = -1;
}

void SurfaceCache::update_cage(const FramedGaussians& gaussians, const std::vector<int>& changed) {
  for (const int v : changed) {
    const Vec3& m = gaussians.mean(size_t(v));
    cage_positions_[size_t(v)] = glm::vec3(float(m.x()), float(m.y()), float(m.z()));
  }
}

// Followed from the capture on, one compute pass after the other (refresh() decides what is worth it).
bool SurfaceCache::follow_edit(long long points) {
  const bool next = has_stored_triangles() && tracked_points_ >= 0 && points == tracked_points_ + 1;
  tracked_points_ = next ? points : -1;
  return next;
}

void SurfaceCache::points_changed(long long points, const std::vector<int>* patches) {
  if (!patches)
    tracked_points_ = -1;
  else if (follow_edit(points))
    blocks_.mark_stale(*patches);
}

void SurfaceCache::all_points_changed(long long points) {
  if (follow_edit(points)) blocks_.mark_all_stale();
}

std::vector<SurfaceBlocks::Moved> SurfaceCache::topology_changed(long long points, int n_patches,
                                                                 const std::vector<int>& new_number,
                                                                 const std::vector<char>& changed) {
  if (!follow_edit(points)) return {};
  // Where a quarter of the patches or more would be captured again, everything is, sooner (refresh()).
  SurfaceBlocks followed = blocks_;
  const std::vector<SurfaceBlocks::Moved> moved = followed.follow(n_patches, new_number, changed);
  const int stale = patch_triangles_agree_ ? followed.stale_patches_past_kept_ends() : followed.stale_patches();
  if (4 * stale > n_patches) {
    tracked_points_ = -1;
    return {};
  }
  copy_back_evaluated();  // by the blocks as they were
  blocks_ = std::move(followed);
  // The kept blocks' triangles, packed in order in the spare buffer, which becomes the stored one;
  // where they all stay where they were (patches added past them), as they are. Their vertices'
  // patches are renumbered as they are copied, or where they lie (render/cache/stored_patch_renumbering.h).
  bool in_place = true, renumbered = false;
  for (const SurfaceBlocks::Moved& m : moved) {
    in_place = in_place && (m.old_first_triangle == m.first_triangle || m.triangles == 0);
    renumbered = renumbered || m.old_first_patch != m.first_patch;
  }
  for (size_t p = 0; p < new_number.size() && !renumbered; ++p)  // their vertices may name moved neighbours
    renumbered = new_number[p] >= 0 && new_number[p] != int(p);
  if (renumbered && !renumbering_) renumbering_ = std::make_unique<StoredPatchRenumbering>(software_renderer());
  if (!in_place) {
    const long long total = blocks_.total();
    reserve(spare_, spare_capacity_, total + total / 8 + 64);
    const std::vector<SurfaceBlocks::Moved> runs = joined_runs(moved);
    if (renumbered)
      renumbering_->copy(buffer_, spare_, runs, new_number);
    else
      copy_stored_triangles(buffer_, spare_, runs);
    std::swap(buffer_, spare_);
    std::swap(capacity_, spare_capacity_);
    glVertexArrayVertexBuffer(vao_, 0, buffer_, 0, kCapturedVertexBytes);
  } else if (renumbered && blocks_.total() > 0) {
    renumbering_->run(buffer_, 3 * blocks_.total(), new_number);
  }
  unweld_all();  // welded anew by the refresh
  topology_pending_ = true;
  check_gl_errors("following a change of topology");
  return moved;
}

bool SurfaceCache::matches(const Key& key, const glm::mat4& view_projection, glm::vec2 viewport) const {
  if (!stored_) return false;
  // A refusal outlasts edits: they leave a uniform level's count as it was, and move an adaptive one
  // little (a capture tried after each would draw every edited frame twice).
  Key compared = key;
  if (refused_) compared.points = key_.points;
  if (!(compared == key_)) return false;
  return key.pixels <= 0.0f || camera_close(view_projection, viewport, key.pixels);
}

// The key's points those that the edits followed since the capture lead to; the rest as for matches().
bool SurfaceCache::can_refresh_to(const Key& key, const glm::mat4& view_projection, glm::vec2 viewport) const {
  if (!has_stored_triangles() || tracked_points_ < 0 || key.points != tracked_points_) return false;
  Key captured = key;
  captured.points = key_.points;
  return matches(captured, view_projection, viewport);
}

// The adaptive rule (see the header): every base edge's projected size (shaders/tess_levels.glsl:
// the projected diameter of the sphere around it), floored at `pixels`, within the hysteresis factor
// of its size under the captured camera; no edge end crossing the eye plane (the shaders give such
// edges level 64).
bool SurfaceCache::camera_close(const glm::mat4& view_projection, glm::vec2 viewport, float pixels) const {
  if (view_projection == view_projection_ && viewport == viewport_) return true;
  struct Projected {
    float pixels;
    bool behind;
  };
  const auto project = [](const glm::mat4& m, glm::vec2 size, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec4 w_row = glm::row(m, 3);
    const float wa = glm::dot(w_row, glm::vec4(a, 1.0f)), wb = glm::dot(w_row, glm::vec4(b, 1.0f));
    const float scale = 0.5f * std::max(glm::length(glm::vec3(glm::row(m, 0))) * size.x,
                                        glm::length(glm::vec3(glm::row(m, 1))) * size.y);
    return Projected{glm::distance(a, b) * scale / (0.5f * (wa + wb)), wa <= 0.0f || wb <= 0.0f};
  };
  const float low = 1.0f / hysteresis_, high = hysteresis_;
  const std::vector<int>& ends = cage_shape_->connectivity.edge_verts;
  for (size_t e = 0; e + 1 < ends.size(); e += 2) {
    const glm::vec3& a = cage_positions_[size_t(ends[e])];
    const glm::vec3& b = cage_positions_[size_t(ends[e + 1])];
    const Projected before = project(view_projection_, viewport_, a, b), now = project(view_projection, viewport, a, b);
    if (before.behind != now.behind) return false;
    if (before.behind) continue;
    const float ratio = std::max(now.pixels, pixels) / std::max(before.pixels, pixels);
    if (!(ratio >= low && ratio <= high)) return false;
  }
  return true;
}

long long SurfaceCache::most_triangles() const { return std::max(1ll, limit_bytes_ / kTriangleBytes); }

void SurfaceCache::set_weld(Weld weld) {
  if (weld == weld_mode_) return;
  weld_mode_ = weld;
  stored_ = false;
  tracked_points_ = -1;
  if (weld == Weld::off) {  // its buffers go
    weld_.reset();
    glNamedBufferData(indices_, 0, nullptr, GL_DYNAMIC_COPY);
    glNamedBufferData(welded_, 0, nullptr, GL_DYNAMIC_COPY);
    glNamedBufferData(parameters_, 0, nullptr, GL_DYNAMIC_COPY);
    index_capacity_ = 0;
  }
}

void SurfaceCache::reserve(unsigned buffer, long long& capacity, long long triangles) const {
  triangles = std::clamp(triangles, 1ll, most_triangles());
  // Grow to fit; shrink where the buffer is four times what is needed.
  if (triangles <= capacity && 4 * triangles >= capacity) return;
  capacity = triangles;
  glNamedBufferData(buffer, GLsizeiptr(capacity * 3 * kCapturedVertexBytes), nullptr, GL_DYNAMIC_COPY);
}

// One feedback session; each block's triangles are counted by its own query (queries of primitives
// written may begin and end while feedback is active), so the blocks lie one after the other.
// With `known` counts (uniform levels: an edit keeps every patch's triangles; or counted from the
// levels) no query is read, and the frame goes on without waiting for the capture; a run of
// consecutive blocks is then one draw, whose triangles the feedback writes in the same order.
bool SurfaceCache::capture_blocks(unsigned buffer, long long capacity, const std::vector<int>& blocks,
                                  const DrawPatches& draw_patches, std::vector<long long>& counts, bool rasterize,
                                  const std::vector<long long>* known, long long* written) {
  const bool checked = known && written;
  while (queries_.size() < (known ? checked ? 1u : 0u : blocks.size()))
    queries_.emplace_back(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
  glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer, 0, GLsizeiptr(capacity * 3 * kCapturedVertexBytes));
  if (!rasterize) glEnable(GL_RASTERIZER_DISCARD);
  glBeginTransformFeedback(GL_TRIANGLES);
  if (checked) glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, queries_[0]);
  for (size_t i = 0; i < blocks.size();) {
    size_t end = i + 1;
    if (known)
      while (end < blocks.size() && blocks[end] == blocks[end - 1] + 1) ++end;
    if (!known) glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, queries_[i]);
    const int first = blocks_.first_patch(blocks[i]);
    draw_patches(first, blocks_.first_patch(blocks[end - 1]) + blocks_.patches_in(blocks[end - 1]) - first);
    if (!known) glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    i = end;
  }
  if (checked) glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
  glEndTransformFeedback();
  glDisable(GL_RASTERIZER_DISCARD);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
  counts.resize(blocks.size());
  long long total = 0;
  for (size_t i = 0; i < blocks.size(); ++i) {
    if (known) {
      counts[i] = (*known)[i];
    } else {
      GLuint64 written = 0;
      glGetQueryObjectui64v(queries_[i], GL_QUERY_RESULT, &written);
      counts[i] = (long long)written;
    }
    total += counts[i];
  }
  if (checked) {
    GLuint64 primitives = 0;
    glGetQueryObjectui64v(queries_[0], GL_QUERY_RESULT, &primitives);
    *written = (long long)primitives;
  }
  check_gl_errors("capturing the surface");
  return known ? total <= capacity : total < capacity;  // a full buffer may have dropped triangles
}

bool SurfaceCache::capture(const Key& key, const glm::mat4& view_projection, glm::vec2 viewport, int n_patches,
                           long long estimate, const DrawPatches& draw_patches, bool rasterize,
                           const std::vector<int>* patch_counts) {
  ++captures_;
  key_ = key;
  view_projection_ = view_projection;
  viewport_ = viewport;
  stored_ = true;
  refused_ = false;
  tracked_points_ = key.points;
  topology_pending_ = false;
  blocks_.reset(n_patches, patches_per_block(n_patches));
  copy_pending_.clear();      // all captured anew
  if (spare_capacity_ > 0) {  // edits start over from here
    glNamedBufferData(spare_, 0, nullptr, GL_DYNAMIC_COPY);
    spare_capacity_ = 0;
  }
  std::vector<int> all(size_t(blocks_.size()));
  for (size_t b = 0; b < all.size(); ++b) all[b] = int(b);
  last_capture_counted_ = patch_counts && capture_counted(all, draw_patches, rasterize, *patch_counts);
  if (last_capture_counted_) {
    weld();
    return true;
  }
  reserve(buffer_, capacity_, estimate);
  std::vector<long long> counts;
  while (!capture_blocks(buffer_, capacity_, all, draw_patches, counts, rasterize)) {
    if (capacity_ >= most_triangles()) {
      refused_ = true;
      tracked_points_ = -1;
      blocks_.reset(0, 1);
      return false;
    }
    reserve(buffer_, capacity_, std::min(2 * capacity_, most_triangles()));
  }
  blocks_.set_counts(counts);
  weld();
  return true;
}

void SurfaceCache::weld(const std::vector<int>& blocks) {
  switch (weld_mode_) {
    case Weld::off:
      return;
    case Weld::at_capture:
      weld_now(blocks);
      return;
    case Weld::when_settled:
      if (blocks.empty()) {
        unweld_all();
      } else if (!weld_all_pending_) {
        std::vector<int> both;
        std::set_union(weld_pending_.begin(), weld_pending_.end(), blocks.begin(), blocks.end(),
                       std::back_inserter(both));
        weld_pending_ = std::move(both);
      }
      return;
  }
}

void SurfaceCache::unweld_all() {
  weld_all_pending_ = true;
  whole_weld_since_ = std::chrono::steady_clock::now();
  whole_weld_frames_ = 0;
  weld_pending_.clear();
}

void SurfaceCache::settle() {
  copy_back_evaluated();
  // With a delay, the first still frame never welds everything: a frame may outlast the delay.
  if (weld_all_pending_ && whole_weld_delay_.count() > 0 &&
      (whole_weld_frames_++ == 0 || std::chrono::steady_clock::now() - whole_weld_since_ < whole_weld_delay_))
    return;
  weld_pending();
}

void SurfaceCache::weld_pending() {
  if (weld_mode_ == Weld::when_settled && has_stored_triangles() && (weld_all_pending_ || !weld_pending_.empty()))
    weld_now(weld_all_pending_ ? std::vector<int>{} : weld_pending_);
}

void SurfaceCache::copy_back_evaluated() {
  if (copy_pending_.empty()) return;
  std::vector<StoredVertexWeld::Range> ranges;
  for (const int b : copy_pending_) ranges.push_back({3 * blocks_.first_triangle(b), 3 * blocks_.triangles(b)});
  weld_->copy_back(buffer_, indices_, welded_, ranges);
  copy_pending_.clear();
}

void SurfaceCache::weld_now(const std::vector<int>& blocks) {
  const long long total = blocks_.total();
  if (total > limit_bytes_ / kWeldedTriangleBytes) {  // drawn as captured
    weld_all_pending_ = true;
    return;
  }
  if (!weld_) weld_ = std::make_unique<StoredVertexWeld>();
  bool all = blocks.empty();
  if (total > index_capacity_ || 4 * total < index_capacity_) {  // new buffers: every block welded again
    index_capacity_ = std::max(total, 1ll);
    glNamedBufferData(indices_, GLsizeiptr(index_capacity_ * 3 * 4), nullptr, GL_DYNAMIC_COPY);
    glNamedBufferData(welded_, GLsizeiptr(index_capacity_ * 3 * kWeldedVertexBytes), nullptr, GL_DYNAMIC_COPY);
    glNamedBufferData(parameters_, GLsizeiptr(index_capacity_ * 3 * kParameterBytes), nullptr, GL_DYNAMIC_COPY);
    all = true;
  }
  if (all) {
    std::vector<long long> starts(size_t(blocks_.size()));
    for (int b = 0; b < blocks_.size(); ++b) starts[size_t(b)] = 3 * blocks_.first_triangle(b);
    weld_->weld(buffer_, indices_, welded_, parameters_, 3 * total, starts);
  } else {  // captured again in the tessellation they had: their vertices keep their indices
    std::vector<StoredVertexWeld::Range> ranges;
    for (const int b : blocks) ranges.push_back({3 * blocks_.first_triangle(b), 3 * blocks_.triangles(b)});
    weld_->weld_again(buffer_, indices_, welded_, parameters_, ranges);
  }
  weld_all_pending_ = false;
  weld_pending_.clear();
}

void SurfaceCache::draw(bool grid) const {
  const bool welded = stored_vertices_welded() && !grid;  // welded copies of a point had their own grids
  const GLuint vao = welded ? welded_vao_ : vao_;
  // Attribute 2 fetched only for a program that reads it.
  if (!welded) {
    if (grid)
      glEnableVertexArrayAttrib(vao, 2);
    else
      glDisableVertexArrayAttrib(vao, 2);
  }
  glBindVertexArray(vao);
  if (welded)
    glDrawElements(GL_TRIANGLES, GLsizei(3 * blocks_.total()), GL_UNSIGNED_INT, nullptr);
  else
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * blocks_.total()));
}

}  // namespace gps
