#pragma once
// The surface cache (issue 12): the triangles the tessellation pipeline produced, captured on the
// GPU by transform feedback and redrawn from that buffer while their inputs are unchanged.
//
// What the stored triangles depend on (SurfaceCache::Key): the plan points (a generation counter
// the renderer bumps with every compute pass: set_mesh, update_vertices, recompute_all) and the
// tessellation levels (uniform level, or adaptive target pixels; the debug mismatch). Adaptive
// levels also depend on the camera; the cache keeps the camera of its capture and re-captures only
// when some base mesh edge's projected length, counted as at least `pixels` (shorter edges get
// level 1 either way), changed by more than the hysteresis factor (default 1.25) since then, or
// crossed the eye plane. Within that, the stored levels stay within the factor of what the live
// pipeline would choose.
#include <glm/glm.hpp>
#include <functional>
#include <vector>

#include "core/covariance_mesh.h"

namespace gps {

class SurfaceCache {
public:
  struct Key {
    long long points = -1;  // generation of the plan points
    float level = 0.0f, pixels = 0.0f;
    bool debug_mismatch = false;
    bool operator==(const Key& o) const {
      return points == o.points && level == o.level && pixels == o.pixels && debug_mismatch == o.debug_mismatch;
    }
  };
  /// One stored vertex: the tessellation evaluation outputs the fragment shader reads.
  static constexpr int kVertexBytes = 10 * 4;  // position, normal, grid (vec3 each), node kind (int)
  static constexpr long long kDefaultLimitBytes = 512ll << 20;

  /// Needs a current GL context.
  SurfaceCache();
  ~SurfaceCache();
  SurfaceCache(const SurfaceCache&) = delete;
  SurfaceCache& operator=(const SurfaceCache&) = delete;

  /// The base mesh (vertex positions and edges) the adaptive hysteresis measures; drops the capture.
  void set_cage(const CovarianceMesh& mesh);
  /// Moved base vertices (the points changed, so the capture is stale anyway).
  void update_cage(const CovarianceMesh& mesh, const std::vector<int>& changed);

  /// Whether the last capture (or its refusal, past the memory limit) stands for these inputs.
  bool current(const Key& key, const glm::mat4& view_projection, glm::vec2 viewport) const;
  /// Captures the triangles that `draw_patches` generates (it issues the patch draws; the caller
  /// has bound a program with the feedback varyings), under transform feedback with the rasteriser
  /// off. `estimate` triangles size the buffer; a full buffer grows and captures again, up to the
  /// memory limit, past which the inputs are refused (drawn live). False when refused.
  bool capture(const Key& key, const glm::mat4& view_projection, glm::vec2 viewport, long long estimate,
               const std::function<void()>& draw_patches);
  /// Whether stored triangles are there to draw (a capture that was not refused).
  bool holds_triangles() const { return stored_ && !refused_; }
  /// Binds the vertex array of the stored triangles and draws them with the bound program.
  void draw() const;

  void set_hysteresis(float factor) { hysteresis_ = factor; }
  void set_limit_bytes(long long bytes) { limit_bytes_ = bytes; }
  /// Captures so far (tests: a frame that should draw stored triangles must not add one).
  int captures() const { return captures_; }
  long long triangles() const { return triangles_; }
  size_t buffer_bytes() const { return size_t(capacity_) * 3 * kVertexBytes; }

private:
  bool camera_close(const glm::mat4& view_projection, glm::vec2 viewport, float pixels) const;
  void reserve(long long triangles);

  unsigned buffer_ = 0, vao_ = 0, written_query_ = 0;
  long long capacity_ = 0;   // triangles the buffer holds
  long long triangles_ = 0;  // triangles stored
  bool stored_ = false, refused_ = false;
  Key key_;
  glm::mat4 view_projection_{1.0f};
  glm::vec2 viewport_{0.0f};
  std::vector<glm::vec3> cage_positions_;
  std::vector<unsigned> cage_edges_;  // index pairs
  float hysteresis_ = 1.25f;
  long long limit_bytes_ = kDefaultLimitBytes;
  int captures_ = 0;
};

}  // namespace gps
