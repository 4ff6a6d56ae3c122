#pragma once
// The surface cache: the triangles the tessellation pipeline produced, captured on the GPU by
// transform feedback and redrawn from that buffer while their inputs are unchanged.
//
// What the stored triangles depend on (SurfaceCache::Key): the plan points (a generation counter
// the renderer bumps with every compute pass: set_mesh, update_vertices, recompute_all) and the
// tessellation levels (uniform level, or adaptive target pixels; the debug mismatch). Adaptive
// levels also depend on the camera; the cache keeps the camera of its capture and re-captures only
// when some base mesh edge's projected size (shaders/tess_levels.glsl: the projected diameter of the
// sphere around it), counted as at least `pixels` (smaller edges get level 1 either way), changed by more than the
// hysteresis factor (default 1.25) since then, or crossed the eye plane. Within that, the stored levels stay within the
// factor of what the live pipeline would choose.
//
// The stored vertices are welded (render/cache/stored_vertex_weld.h) and drawn by index, as a welded
// static buffer is. On a GPU right after each capture or refresh (Weld::at_capture). On llvmpipe
// (Weld::when_settled) by the first frame whose inputs the stored triangles match (settle()): there
// the weld costs an edit's frame more than it saves it, so the frames of a drag draw the triangles as
// captured and the frames after it welded. A weld of every stored vertex (after a capture or a change
// of topology) may further wait until the triangles have stayed as they are for a while
// (set_whole_weld_delay): an editor then welds while its user pauses, not in the frame after an operation.
//
// Edits: triangles are captured in blocks of consecutive patches (render/cache/surface_blocks.h), each
// counted by its own query. An edit reports the patches it changed (points_changed); the next frame
// brings only their blocks up to date (refresh). Where a block's tessellation stays (uniform levels;
// adaptive ones where the level check finds every patch's levels unchanged under the capture's
// camera, render/cache/stored_patch_levels.h) and the vertices are welded, a compute pass evaluates its
// welded vertices again at the parameters they were captured at (render/cache/stored_vertex_evaluation.h):
// each point once, on all of llvmpipe's threads; at uniform levels only from evaluated_from_level().
// The captured copies of those vertices, which only a grid frame, a capture of some blocks again and
// the read-back use, are brought up to date later, by the next of those or of a still frame
// (settle()): so the frames of a drag do not copy them.
// The other stale blocks are captured again, under the camera of the capture, into a scratch buffer,
// and copied into place (or, where adaptive levels changed a block's count, the clean and the new
// blocks are assembled in a spare buffer, which then becomes the stored one); where over half of the
// patches would be captured so, the whole surface is captured again. A change of topology whose
// patches mostly keep their numbers is followed the same way (topology_changed; docs/surface_cache.md).
#include <glm/glm.hpp>
#include <chrono>
#include <functional>
#include <memory>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/evaluation/triangle_mesh.h"
#include "render/cache/stored_patch_levels.h"
#include "render/cache/stored_patch_renumbering.h"
#include "render/cache/stored_vertex_evaluation.h"
#include "render/cache/stored_vertex_weld.h"
#include "render/cache/surface_blocks.h"
#include "render/gl/normalised_frame.h"
#include "render/gl/gl_object.h"

namespace gps {

class SurfaceCache {
public:
  /// What the stored triangles depend on but the camera: the generation of the plan points and the
  /// tessellation levels.
  struct Key {
    long long points = -1;  // generation of the plan points
    float level = 0.0f, pixels = 0.0f;
    bool mismatched_edge_levels = false;
    bool operator==(const Key& o) const {
      return points == o.points && level == o.level && pixels == o.pixels &&
             mismatched_edge_levels == o.mismatched_edge_levels;
    }
  };
  /// When the stored vertices are welded: never, after each capture and refresh, or by the first
  /// frame that draws them unchanged (settle()).
  enum class Weld { off, at_capture, when_settled };
  /// Issues the patch draws of patches [first, first + count) (the caller has bound a program with
  /// the feedback varyings).
  using DrawPatches = std::function<void(int first, int count)>;
  /// Evaluates the welded vertices of blocks again (render/cache/stored_vertex_evaluation.h), as many per
  /// block as the buffer `welded_counts` holds, with the welded vertex and parameter buffers bound.
  using EvaluateWelded =
      std::function<void(const std::vector<StoredVertexEvaluation::Block>& blocks, unsigned welded_counts)>;
  /// At adaptive levels: per block (its patches listed), whether an edit changed any patch's levels
  /// under the capture's camera (render/cache/stored_patch_levels.h, recorded at each adaptive capture).
  using LevelsChanged = std::function<std::vector<char>(const std::vector<StoredPatchLevels::Block>& blocks)>;
  /// The triangle counts of `patches` under the capture's camera (render/cache/patch_triangle_counts.h);
  /// empty where they cannot be had.
  using PatchTriangles = std::function<std::vector<int>(const std::vector<int>& patches)>;

  /// Needs a current GL context.
  SurfaceCache();
  SurfaceCache(const SurfaceCache&) = delete;
  SurfaceCache& operator=(const SurfaceCache&) = delete;

  // What changed.

  /// The base mesh (vertex positions and edges) the adaptive hysteresis measures; drops the capture,
  /// unless `follow` (a change of topology that topology_changed() reports next).
  void set_cage(const CovarianceMesh& mesh, const FramedGaussians& gaussians, bool follow = false);
  /// Moved base vertices (for the hysteresis; points_changed says what the edit changed).
  void update_cage(const FramedGaussians& gaussians, const std::vector<int>& changed);
  /// The base vertices' positions as the last set_cage and update_cage gave them, in float.
  const std::vector<glm::vec3>& cage_positions() const { return cage_positions_; }
  /// A compute pass made plan points of generation `points`, changing the triangles of `patches`
  /// (nullptr: of all patches, not followed as an edit: captured again). An edit is followed from a
  /// capture on, one compute pass after the other; any other change is captured again.
  void points_changed(long long points, const std::vector<int>* patches);
  /// An edit's compute pass over everything (most of the mesh moved) made plan points of
  /// generation `points`: every block is stale, followed as an edit's.
  void all_points_changed(long long points);
  /// A change of topology made plan points of generation `points` for `n_patches` patches: per patch
  /// before, `new_number` gives its number now (−1: none), and `changed` flags the patches now whose
  /// triangles change (render/pipeline/kept_surface_triangles.h). Followed as an edit: the blocks whose
  /// patches all keep their triangles stay, renumbered (SurfaceBlocks::follow), the other patches
  /// form stale blocks, which the next refresh captures whatever their levels, and everything is
  /// welded anew. Returns the blocks kept (empty where the change is not followed: captured again).
  std::vector<SurfaceBlocks::Moved> topology_changed(long long points, int n_patches,
                                                     const std::vector<int>& new_number,
                                                     const std::vector<char>& changed);

  // What a frame asks.

  /// Whether the last capture, or its refusal past the memory limit, was made for these inputs: the
  /// key (a refusal's but for the plan points: it stands for edits), and at adaptive levels a camera
  /// within the hysteresis of the capture's. Such a frame neither captures nor refreshes: it draws
  /// the stored triangles, or live where they were refused.
  bool matches(const Key& key, const glm::mat4& view_projection, glm::vec2 viewport) const;
  /// Whether refresh() brings the stored triangles to these inputs: they differ from the capture's
  /// only by the plan points of edits followed since, and the camera matches as for matches().
  bool can_refresh_to(const Key& key, const glm::mat4& view_projection, glm::vec2 viewport) const;
  /// Whether stored triangles are there to draw: a capture that was not refused.
  bool has_stored_triangles() const { return stored_ && !refused_; }
  /// Whether the stored vertices are welded, none left for a later weld: draw() draws them by index,
  /// but for the grid.
  bool stored_vertices_welded() const { return weld_mode_ != Weld::off && !weld_all_pending_ && weld_pending_.empty(); }

  // What a frame does.

  /// Captures the triangles of all `n_patches` that `draw_patches` generates, block by block,
  /// under transform feedback, with the rasteriser off or (`rasterize`: a frame drawn as it is
  /// captured) on. `estimate` triangles size the buffer; a full buffer grows and captures again, up
  /// to the memory limit, past which the inputs are refused (drawn live). False when refused.
  /// With `patch_counts` (each patch's triangles, from its levels: where counts_captures()), the
  /// blocks' counts are their sums and the buffer is sized by them: the patches go in one draw, whose
  /// triangles one query checks, where a query per block would pause a GPU's feedback once per block.
  /// Counts that miss the query's are not used again: the capture is made block by block.
  bool capture(const Key& key, const glm::mat4& view_projection, glm::vec2 viewport, int n_patches, long long estimate,
               const DrawPatches& draw_patches, bool rasterize = false, const std::vector<int>* patch_counts = nullptr);
  /// Whether a capture, and a refresh's capture of blocks whose counts changed, take the patches'
  /// triangle counts: on (the default) and the counts agreed with the queries of the last capture
  /// made block by block (check_patch_triangles()), and with every counted capture since.
  bool counts_captures() const { return counted_captures_ && patch_triangles_agree_; }
  void set_counted_captures(bool counted) { counted_captures_ = counted; }
  /// Whether the last capture took the patches' counts (else it queried each block, and
  /// check_patch_triangles() may check the counts against it).
  bool last_capture_counted() const { return last_capture_counted_; }
  /// The camera of the capture, under which refresh() captures blocks again and the level check
  /// evaluates adaptive levels, as the capture did.
  const glm::mat4& captured_view_projection() const { return view_projection_; }
  glm::vec2 captured_viewport() const { return viewport_; }
  /// Brings the stale blocks to `key` (where can_refresh_to()). Blocks whose tessellation stays
  /// (uniform levels from evaluated_from_level(); adaptive ones that `levels_changed` leaves alone)
  /// with the vertices welded: by evaluating the welded vertices again (`evaluate_welded`, where
  /// given). The others by capturing them again, for which the caller has set the capture camera
  /// above in the program's uniforms. False where capturing them again is not worth it (over half of
  /// the patches) or did not fit the memory limit (capture everything then).
  /// After a change of topology, a block that keeps some of its patches at its ends is split there by
  /// their `patch_triangles` (where check_patch_triangles() found such counts right), and only the
  /// patches between are captured again.
  bool refresh(const Key& key, const DrawPatches& draw_patches, const EvaluateWelded& evaluate_welded = {},
               const LevelsChanged& levels_changed = {}, const PatchTriangles& patch_triangles = {});
  /// After a capture, the patches whose triangle counts check_patch_triangles() takes: those of every
  /// block, or of blocks spread evenly over the surface, up to kCheckedPatches.
  std::vector<int> checked_patches() const;
  /// Their triangle counts found from their levels, in that order, checked against the count of each
  /// of their blocks. Where all agree (and no counted capture ever missed its query), refresh() may
  /// locate patches inside blocks by such counts.
  void check_patch_triangles(const std::vector<int>& counts);
  static constexpr int kCheckedPatches = 8192;
  /// The uniform level from which an edit evaluates welded vertices again: kSettledEvaluatedFromLevel
  /// where the weld waits for a still frame; every level where it welds at capture (a GPU: there
  /// transform feedback costs more than the compute passes).
  float evaluated_from_level() const { return weld_mode_ == Weld::when_settled ? kSettledEvaluatedFromLevel : 0.0f; }
  /// For a frame that matches(): brings the captured copies of evaluated vertices up to date and
  /// welds what Weld::when_settled left unwelded (a weld of everything once the delay has passed).
  void settle();
  /// Whether settle() has nothing left to do: a frame that matches() then draws what the last drew
  /// (false while a weld waits for its delay: the frames until then draw, and the last welds).
  bool settled() const {
    const bool weld_waits =
        weld_mode_ == Weld::when_settled && has_stored_triangles() && (weld_all_pending_ || !weld_pending_.empty());
    return copy_pending_.empty() && !weld_waits;
  }
  /// Brings the captured copies of the vertices that edits evaluated again up to date (a compute
  /// pass: call before binding the frame's program), as a frame that draws the grid needs.
  void copy_back_evaluated();
  /// Binds the vertex array of the stored triangles and draws them with the bound program, which
  /// reads the tessellation grid (attribute 2) where `grid`: welded where they are, but with the grid
  /// (the welded copies of a point on a patch edge had each their patch's grid; copy_back_evaluated() first).
  void draw(bool grid) const;

  // Read back (benchmarks, tests).

  /// The stored triangles read back, vertices with bit-identical position and normal welded (shared
  /// patch edges are bit-exact): the benchmark's static-buffer floor for exactly these triangles.
  /// Their captured copies, brought up to date first (copy_back_evaluated()). Positions in world
  /// coordinates: the stored ones lie in the frame of set_frame().
  TriangleMesh stored_triangles();
  /// The captured vertices as stored, 12 floats each (kCapturedVertexBytes), their copies of evaluated
  /// vertices brought up to date first: what a capture of the same inputs stores, bit for bit.
  std::vector<float> captured_vertices();
  /// The frame the captured positions lie in (render/gl/normalised_frame.h).
  void set_frame(const NormalisedFrame& frame) { frame_ = frame; }
  /// The distinct vertices a cached frame fetches (read back): where welded, the distinct indices;
  /// else three per triangle.
  long long distinct_vertices() const;

  // Settings.

  /// When stored vertices are welded (default: at_capture, or when_settled where the renderer is
  /// software); a change drops the stored triangles.
  void set_weld(Weld weld);
  Weld weld_mode() const { return weld_mode_; }
  /// When settled: how long the stored triangles stay unchanged before a weld of all of them, which
  /// then also waits for the second frame that draws them unchanged (default 0: the first such frame
  /// welds). Partial welds of refreshed blocks do not wait.
  void set_whole_weld_delay(std::chrono::duration<double> delay) { whole_weld_delay_ = delay; }
  /// The delay an interactive program gives: a pause of its user.
  static constexpr std::chrono::duration<double> kPauseWeldDelay{0.3};
  /// The factor by which a base edge's projected size may change before adaptive levels capture
  /// again (default 1.25).
  void set_hysteresis(float factor) { hysteresis_ = factor; }

  // Memory.

  /// One captured vertex: the tessellation evaluation outputs the fragment shader reads (position,
  /// normal · 2^(node kind), grid: vec3 each), then the patch and (u, v) it was evaluated at (the
  /// canonical patch on patch edges; shaders/limit_point_tese.glsl), for evaluating it again.
  static constexpr int kCapturedVertexBytes = 12 * 4;
  /// One welded vertex: position and normal · 2^(node kind); no grid (the copies of a point on a
  /// patch edge each had their patch's: a frame that draws the grid draws them as captured).
  static constexpr int kWeldedVertexBytes = 6 * 4;
  /// What a welded vertex keeps of those parameters.
  static constexpr int kParameterBytes = 3 * 4;
  /// What a stored triangle takes of the memory limit: its captured vertices. Welded, also their
  /// indices, the welded vertices and, while they are welded, the weld's table and prefix sum:
  /// triangles past the limit welded are drawn as captured.
  static constexpr int kTriangleBytes = 3 * kCapturedVertexBytes;
  static constexpr int kWeldedTriangleBytes =
      3 * (kCapturedVertexBytes + kWeldedVertexBytes + kParameterBytes + 4 + StoredVertexWeld::kTableBytesPerVertex);
  /// The memory limit: a sixteenth of the device's memory (render/gl/device_memory.h; a GPU's, or the
  /// machine's for llvmpipe), at least kLeastLimitBytes and at most kMostLimitBytes, which keeps
  /// every buffer under 2 GiB: NVIDIA's driver (580) ends transform feedback into a larger one early,
  /// filling and counting only what lies past a wrap at 4 GiB.
  static constexpr long long kLeastLimitBytes = 512ll << 20;
  static constexpr long long kMostLimitBytes = (2ll << 30) - 1;
  static constexpr int kDeviceMemoryShare = 16;
  void set_limit_bytes(long long bytes) { limit_bytes_ = bytes; }
  long long limit_bytes() const { return limit_bytes_; }
  /// The bytes of the cache's buffers.
  size_t buffer_bytes() const {
    return size_t(capacity_ + scratch_capacity_ + spare_capacity_) * 3 * kCapturedVertexBytes +
           size_t(index_capacity_) * 3 * (kWeldedVertexBytes + kParameterBytes + 4) + (weld_ ? weld_->bytes() : 0);
  }

  // Counts (statistics, benchmarks, tests).

  /// Full captures so far (tests: a frame that should draw stored triangles must not add one).
  int captures() const { return captures_; }
  /// Refreshes so far, and the patches the last one brought up to date (those of its stale blocks).
  int refreshes() const { return refreshes_; }
  int refreshed_patches() const { return refreshed_patches_; }
  /// Of those, the patches whose welded vertices it evaluated again (the rest it captured again).
  int evaluated_patches() const { return evaluated_patches_; }
  /// The stored triangles' count.
  long long triangles() const { return blocks_.total(); }
  /// The blocks they are stored in.
  int blocks() const { return blocks_.size(); }

private:
  NormalisedFrame frame_;
  /// Where the weld waits for a still frame (llvmpipe), an edit evaluates the welded vertices again
  /// instead of capturing its blocks again only from this uniform level on: below, its three compute
  /// passes cost more than the capture.
  static constexpr float kSettledEvaluatedFromLevel = 8.0f;
  /// From a uniform level of 8 on, a block's welded vertices are fewer than a third of its capture
  /// slots (a quad patch at level L has (L + 1)² of 6 L², a half-size one at ⌈L/2⌉ and a triangle at L
  /// alike), the bound that sizes the evaluation's dispatches; below, all of its slots.
  static constexpr float kThirdOfSlotsFromLevel = 8.0f;

  bool camera_close(const glm::mat4& view_projection, glm::vec2 viewport, float pixels) const;
  /// The blocks checked_patches() lists.
  std::vector<int> checked_blocks() const;
  /// Follows plan points of generation `points` as an edit's where they come one compute pass after
  /// those followed so far (true); else stops following edits until the next capture (false).
  bool follow_edit(long long points);
  long long most_triangles() const;
  void reserve(unsigned buffer, long long& capacity, long long triangles) const;
  /// Captures `blocks` one after the other into `buffer` from its start; their counts (counted by a
  /// query per block, or where `known` is given, those: consecutive blocks then go in one draw); false
  /// where the buffer was full (and some triangles may be missing).
  /// `written`, where given with `known`: set to the triangles the feedback wrote, by one query.
  bool capture_blocks(unsigned buffer, long long capacity, const std::vector<int>& blocks,
                      const DrawPatches& draw_patches, std::vector<long long>& counts, bool rasterize = false,
                      const std::vector<long long>* known = nullptr, long long* written = nullptr);
  /// capture()'s capture of every block by their patches' counts; false where the buffer would not
  /// fit them or the feedback wrote another number of triangles (counts_missed_ then).
  bool capture_counted(const std::vector<int>& all, const DrawPatches& draw_patches, bool rasterize,
                       const std::vector<int>& patch_counts);
  /// Per block of `blocks`: the sum of its patches' triangle counts (`patch_triangles`); empty where
  /// they cannot be had.
  std::vector<long long> counted_triangles(const std::vector<int>& blocks, const PatchTriangles& patch_triangles) const;
  /// The patches of `blocks`, in their order.
  std::vector<int> patches_of(const std::vector<int>& blocks) const;
  /// Per block of `blocks`: the sum of `counts`, one per patch of patches_of(blocks); empty where
  /// `counts` has another length.
  std::vector<long long> block_sums(const std::vector<int>& blocks, const std::vector<int>& counts) const;
  void evaluate_again(const std::vector<int>& blocks, bool third, const EvaluateWelded& evaluate_welded);
  /// Welds now what Weld::when_settled left unwelded.
  void weld_pending();
  /// Every block left to weld when settled, from now (the delay counts from here).
  void unweld_all();
  bool capture_again(const std::vector<int>& blocks, const DrawPatches& draw_patches, bool kept,
                     const std::vector<long long>& counted);
  /// Counts a refresh: the stale blocks are fresh, the stored triangles those of `key`.
  bool refreshed(const Key& key);
  /// The stored triangles with `blocks` replaced by the scratch buffer's, of new counts.
  bool assemble(const std::vector<int>& blocks, const std::vector<long long>& counts);
  /// The scratch buffer's `blocks`, captured one after the other with `counts`, copied to where the
  /// blocks lie in the stored buffer.
  void copy_into_place(const std::vector<int>& blocks, const std::vector<long long>& counts);
  /// The stored vertices of `blocks` changed, captured again in the tessellation they had (each keeps
  /// its welded vertex), or where empty all of them: welds them now or, when settled, later.
  void weld(const std::vector<int>& blocks = {});
  /// Welds them into the index and welded vertex buffers.
  void weld_now(const std::vector<int>& blocks);

  GlBuffer buffer_, scratch_, spare_, indices_, welded_, parameters_;
  GlVertexArray vao_, welded_vao_;
  long long index_capacity_ = 0;            // triangles the index, welded vertex and parameter buffers hold
  std::unique_ptr<StoredVertexWeld> weld_;  // made at the first weld
  std::unique_ptr<StoredPatchRenumbering> renumbering_;  // made at the first change of topology that needs it
  Weld weld_mode_;
  bool weld_all_pending_ = true;   // when settled: every block to weld
  std::chrono::duration<double> whole_weld_delay_{0.0};
  std::chrono::steady_clock::time_point whole_weld_since_{};  // when every block last became unwelded
  int whole_weld_frames_ = 0;                                 // the still frames since
  std::vector<int> weld_pending_;  // else these, in order
  std::vector<int>
      copy_pending_;  // blocks whose evaluated welded vertices are not yet copied to their captured ones, in order
  std::vector<GlQuery> queries_;                                        // one per block of a capture
  long long capacity_ = 0, scratch_capacity_ = 0, spare_capacity_ = 0;  // triangles the buffers hold
  SurfaceBlocks blocks_;
  long long tracked_points_ = -1;  // the points the stale blocks lead to (−1: untracked)
  bool stored_ = false, refused_ = false;
  bool topology_pending_ = false;  // the stale blocks follow a change of topology: captured again
  // The last check_patch_triangles() found every block's count, and no counted capture missed its query.
  bool patch_triangles_agree_ = false;
  bool counted_captures_ = true;
  bool counts_missed_ = false;  // a counted capture's query found another total: never agreed again
  bool last_capture_counted_ = false;
  Key key_;
  glm::mat4 view_projection_{1.0f};
  glm::vec2 viewport_{0.0f};
  std::vector<glm::vec3> cage_positions_;
  std::shared_ptr<const MeshShape> cage_shape_ = empty_mesh_shape();  // the edges, as index pairs
  float hysteresis_ = 1.25f;
  long long limit_bytes_;
  int captures_ = 0, refreshes_ = 0, refreshed_patches_ = 0, evaluated_patches_ = 0;
};

}  // namespace gps
