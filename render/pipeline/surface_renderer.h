#pragma once
// The GPU pipeline of docs/design.md §2, a facade over its parts: the planned surface's tables uploaded
// once per topology (render/pipeline/plan_buffers.h); per edit the compute passes map changed vertices to 9D
// and apply the stencils (render/pipeline/dual_stencil_pass.h); per frame GL_PATCHES with tessellation
// shaders evaluate the limit surface (render/pipeline/patch_draw.h), or the surface cache redraws stored
// triangles (render/cache/surface_cache.h), shaded by MatCap; overlays of ellipsoids and the base mesh
// (render/overlays/cage_lines.h); static triangles as the benchmark floor (render/pipeline/static_triangles.h).
#include <glm/glm.hpp>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/plans/patch_readers.h"
#include "core/plans/planned_surface.h"
#include "core/evaluation/triangle_mesh.h"
#include "view/camera.h"
#include "render/overlays/cage_lines.h"
#include "render/pipeline/corner_limit_pass.h"
#include "render/gl/draw_options.h"
#include "render/pipeline/dual_stencil_pass.h"
#include "render/overlays/ellipsoid_overlay.h"
#include "render/gl/gl_object.h"
#include "render/gl/gpu_pass_timer.h"
#include "render/gl/query_ring.h"
#include "render/image/image.h"
#include "render/pipeline/patch_draw.h"
#include "render/pipeline/plan_buffers.h"
#include "render/gl/point_precision.h"
#include "render/gl/render_target.h"
#include "render/gl/shader_program.h"
#include "render/pipeline/static_triangles.h"
#include "render/cache/stored_patch_levels.h"
#include "render/cache/stored_vertex_evaluation.h"
#include "render/cache/patch_triangle_counts.h"
#include "render/cache/surface_cache.h"

namespace gps {

class SurfaceRenderer {
public:
  /// Needs a current GL 4.5 context.
  SurfaceRenderer();
  SurfaceRenderer(const SurfaceRenderer&) = delete;
  SurfaceRenderer& operator=(const SurfaceRenderer&) = delete;

  /// New topology: uploads `surface_tables` (built by core for this mesh; the renderer keeps them), then a
  /// full compute pass in `frame`, with plan points in the precision the mesh's Gaussians need
  /// (render/gl/point_precision.h). Throws gps::Error, before anything changes, where the tables
  /// exceed the device's storage block size or the driver refuses the double programs.
  void set_mesh(const CovarianceMesh& mesh, SurfaceTables surface_tables, const NormalisedFrame& frame);
  /// New topology, the tables of a replanner's `change` (SurfaceReplanner::last_change), with each
  /// vertex's index in the previous mesh (`origin`, as the replanner took it; empty: the same index):
  /// as set_mesh, bit for bit. Where this renderer shows the tables the change went from, in the same
  /// frame and precision, the corner pass evaluates again only the patches whose plans, neighbours or
  /// points changed, and copies the others' output; otherwise everything. In the same frame and
  /// precision, the base Gaussians that did not change are copied on the GPU, not uploaded again.
  /// Where the plans stay and every Gaussian moved by one rotation, positive scale and translation
  /// (render/gl/moved_frame.h), the frame moves with them instead, whatever `frame` says, and
  /// nothing is evaluated again: the surface drawn is the evaluated one moved, to within rounding.
  void set_mesh(const CovarianceMesh& mesh, SurfaceTables surface_tables, const NormalisedFrame& frame,
                const PlanChange& change, const std::vector<int>& origin) {
    set_mesh(mesh, std::make_shared<const SurfaceTables>(std::move(surface_tables)), frame, change, origin);
  }
  /// The same with tables it shares (a replanner's, SurfaceReplanner::shared_tables): kept without a copy.
  void set_mesh(const CovarianceMesh& mesh, std::shared_ptr<const SurfaceTables> surface_tables,
                const NormalisedFrame& frame, const PlanChange& change, const std::vector<int>& origin);
  /// The same with the tables of `surface`, in the mesh's own frame.
  void set_mesh(const CovarianceMesh& mesh, PlannedSurface surface) {
    set_mesh(mesh, std::move(surface), NormalisedFrame::of(mesh));
  }
  /// The same, evaluated in `frame` instead of the mesh's own (a rebuild that must match edits made
  /// in an earlier frame).
  void set_mesh(const CovarianceMesh& mesh, PlannedSurface surface, const NormalisedFrame& frame) {
    set_mesh(mesh, std::move(surface).release_tables(), frame);
  }
  /// The same with the tables core plans under `options` (Loop for triangles only, else
  /// Catmull-Clark); no CPU plan points are computed, the GPU computes its own.
  void set_mesh(const CovarianceMesh& mesh, const PlanOptions& options) {
    set_mesh(mesh, build_surface_plans(mesh, options), NormalisedFrame::of(mesh));
  }
  /// The same with the default options: the scheme that fits the mesh, exact plans.
  void set_mesh(const CovarianceMesh& mesh) { set_mesh(mesh, PlanOptions{}); }
  /// An edit: uploads the changed vertices (those listed whose Gaussian changed) and re-runs the compute passes on what
  /// depends on them (past core's update_everything share of the vertices: whole buffers and the full passes); the
  /// surface cache learns which patches changed (core/plans/patch_readers.h) and re-captures only those.
  /// An edit that changes the precision the Gaussians need uploads and computes everything again. An
  /// edit of every vertex by one rotation, positive scale and translation moves the frame instead, as set_mesh.
  void update_vertices(const CovarianceMesh& mesh, const std::vector<int>& changed);
  /// The compute passes over every vertex and stencil row (as after set_mesh), for benchmarks.
  void recompute_all() { run_compute(nullptr); }
  /// Triangles to draw with DrawOptions::static_triangles (CPU tessellation, reference subdivision), in
  /// world coordinates less `origin`; kept in the frame of the last set_mesh, as the patches are.
  void set_triangles(const TriangleMesh& triangles, const Vec3& origin = Vec3::Zero());
  void set_triangles(const PlacedTriangles& placed) { set_triangles(placed.triangles, placed.origin); }
  void set_matcap(const Image& matcap);

  void draw(const RenderTarget& target, const Camera& camera, const DrawOptions& options);
  /// Whether draw(target, camera, options) would draw again what the last draw left in `target`: the
  /// last draw was into it, with the same camera and options; nothing it draws has changed since (a
  /// mesh, an edit, the MatCap, the static triangles); and the surface cache had nothing left to
  /// settle. A caller that has drawn nothing over the target since may keep it as it is.
  bool draws_as_last(const RenderTarget& target, const Camera& camera, const DrawOptions& options) const;
  /// The vertices the tessellator generates for `options` in a width × height viewport (no
  /// rasterisation), of the patches [first_patch, first_patch + n_patches) (n_patches < 0: to the last).
  std::vector<TessellatedVertex> capture_vertices(const Camera& camera, const DrawOptions& options, int width,
                                                  int height, int first_patch = 0, int n_patches = -1);
  /// How many triangles the tessellator generates of each patch for `options` in a width × height
  /// viewport, found from the patches' levels (render/cache/patch_triangle_counts.h), not counted.
  std::vector<int> patch_triangle_counts(const Camera& camera, const DrawOptions& options, int width, int height);
  /// The same with positions in frame() coordinates.
  std::vector<TessellatedVertex> capture_frame_vertices(const Camera& camera, const DrawOptions& options, int width,
                                                        int height, int first_patch = 0, int n_patches = -1);
  /// The limit point at every patch corner as the last compute pass left it, once per corner point,
  /// in frame() coordinates: the surface evaluated already, read back without a draw.
  std::vector<glm::dvec3> corner_limit_points() const;

  /// The stored triangles of DrawOptions::surface_cache (its capture count, hysteresis, limit).
  SurfaceCache& surface_cache() {
    ++revision_;  // its settings may change what a draw draws
    return cache_;
  }
  const SurfaceCache& surface_cache() const { return cache_; }
  /// The surface cache's GPU buffers and the levels its adaptive capture recorded.
  size_t surface_cache_bytes() const { return cache_.buffer_bytes() + stored_levels_.bytes(); }

  /// Times the compute passes ("9D + stencils") and each drawn layer ("surface", "ellipsoids",
  /// "mesh lines") into `timer`; nullptr (the default) times nothing.
  void set_pass_timer(GpuPassTimer* timer) { timer_ = timer; }
  /// Counts triangles and vertices of each patch draw and the vertices of each draw from the surface
  /// cache (off by default: headless renders pay nothing).
  void set_collect_statistics(bool collect);
  /// The figures of the newest patch draw whose queries finished: drawing every frame, they lag a
  /// frame or two (the queries are never waited for). Zero counts before any finished.
  DrawStatistics last_statistics();

  const SurfaceTables& tables() const;
  /// The frame the GPU evaluates the mesh in, fixed by set_mesh (render/gl/normalised_frame.h).
  const NormalisedFrame& frame() const { return frame_; }
  /// The precision of the plan points, as the mesh's Gaussians need it.
  PointPrecision point_precision() const { return buffers_.precision(); }
  /// The plan points as the compute passes left them (12 floats each: q in three vec4), of the mesh
  /// in frame() (frame().to_frame(mesh)).
  std::vector<float> read_points() const { return buffers_.read_points(tables().stencils.n_points()); }
  /// The corner slots the last compute pass evaluated (every patch corner after a full pass).
  int last_corner_slots() const { return last_corner_slots_; }
  /// The corner pass's output as the last compute pass left it (PlanBuffers::read_corner_pass).
  std::vector<float> read_corner_pass() const { return buffers_.read_corner_pass(); }
  /// The words of the tables' buffer at `binding` (render/gl/gpu_layout.h), as the uploads left them.
  std::vector<uint32_t> read_table_buffer(int binding) const { return buffers_.read_words(binding); }
  /// GPU memory held by the pipeline's buffers, in bytes.
  size_t buffer_bytes() const { return buffers_.bytes(); }

private:
  // Tests lower the device's limits (tests/support/device_limits.h).
  friend struct DeviceLimitsForTests;

  /// The buffers, overlays, passes and surface cache after an edit of the `changed` vertices, whose
  /// framed Gaussians and point precision are already those of the edited mesh (update_vertices).
  void follow_edit(const std::vector<int>& changed);
  /// Where `mesh` is the one shown moved whole (render/gl/moved_frame.h): the frame moved with it,
  /// the Gaussians held framed anew, and true; else false, and nothing changed.
  bool follow_move(const CovarianceMesh& mesh);
  /// The compute passes for `changed` base vertices, or all (nullptr; an `edit` of most of them
  /// where set, which the surface cache follows as such).
  void run_compute(const std::vector<int>* changed, bool edit = false);
  /// The compute passes after a change of topology to `mesh` that kept `change.kept` patches of `before`
  /// (the previous tables), where the `changed` vertices' Gaussians are new or changed (changed_gaussians;
  /// `origin`: as set_mesh takes it): every point (the changed vertices' and every stencil row where the
  /// other base points were carried over, `points_carried`), and the corners of the patches whose output
  /// is not kept.
  void run_compute_kept(const CovarianceMesh& mesh, const SurfaceTables& before, const std::vector<int>& changed,
                        const PlanChange& change, const std::vector<int>& origin, bool points_carried);
  /// The programs and buffers of every pass for points of `precision` (the buffers still to upload);
  /// where the driver refuses a program, throws gps::Error with every pass as it was.
  void use_point_precision(PointPrecision precision);
  /// The stencil rows a change of topology that carried the points (run_compute_kept) leaves to compute:
  /// those not kept (PlanChange::kept_rows), and the kept ones that read a vertex of `before` whose
  /// Gaussian changed.
  std::vector<int> rows_not_carried(const SurfaceTables& before, const std::vector<int>& changed,
                                    const PlanChange& change, const std::vector<int>& origin);
  /// Which stencil rows read each base vertex, found when first asked for after a change of tables.
  const StencilDependents& dependents();
  /// The first patch of each face of mesh_shape_ in tables_ (first_patches), built once per topology.
  const std::vector<int>& face_first_patches();
  /// The patches whose triangles an edit of `changed` vertices and the stencil `rows` reading them changes.
  std::vector<int> changed_patches(const std::vector<int>& changed, const std::vector<int>& rows);
  /// How a frame uses the surface cache: it draws the stored triangles, it was drawn while it was
  /// captured, or it is drawn live (the cache refused these inputs).
  enum class CacheFrame { stored, drawn, live };
  /// The surface cache's inputs for a frame of these options.
  SurfaceCache::Key cache_key(const DrawOptions& options) const;
  /// The surface cache's work for a frame before its target is cleared: an edit's refresh (compute
  /// passes, captures with the rasteriser off), or a still frame's settling, and the captured copies
  /// a grid frame reads. True where the cache then matches the frame's inputs (SurfaceCache::matches).
  bool prepare_cache(const Camera& camera, const DrawOptions& options, float aspect, int width, int height);
  /// A capture of every patch (drawing the frame as it goes), where prepare_cache() left the cache
  /// not matching the frame.
  CacheFrame capture_cache(const Camera& camera, const DrawOptions& options, float aspect, int width, int height);
  /// The triangle counts of `patches` at the levels of `options` under this camera and viewport.
  std::vector<int> triangle_counts(const glm::mat4& view_projection, glm::vec2 viewport, const DrawOptions& options,
                                   const std::vector<int>& patches);
  /// The same for every patch.
  std::vector<int> all_triangle_counts(const glm::mat4& view_projection, glm::vec2 viewport,
                                       const DrawOptions& options);
  /// The stored triangles with the bound program, counted while collecting statistics.
  void draw_cache(bool grid);
  /// Whether a cached frame of these options draws the quads' wireframe: their tessellation grid,
  /// stored with the captured vertices (triangles' comes from a geometry stage).
  bool draws_grid(const DrawOptions& o) const { return o.wireframe && shape() == PatchShape::quad; }
  PatchShape shape() const { return tables().plans.shape; }
  int n_patches() const { return tables().plans.n_patches(); }

  std::shared_ptr<const SurfaceTables> tables_ = std::make_shared<const SurfaceTables>();
  std::optional<StencilDependents> dependents_;  // of tables_'s stencils, once asked for (dependents())
  std::unique_ptr<const PatchReaders> readers_;  // built at the first edit of many vertices the cache can follow
  /// Below one vertex in this many, an edit's patches are found around it (patches_changed_near).
  static constexpr size_t kNearEditDivisor = 64;
  std::shared_ptr<const MeshShape> mesh_shape_ = empty_mesh_shape();  // the faces tables_ plan
  std::optional<std::vector<int>> first_patches_;                     // of mesh_shape_ in tables_, once asked for
  size_t near_patches_listed_ = 0;                                    // by the lookups around edits since tables_ came
  PlanBuffers buffers_;
  MeshPointPrecision point_precision_;  // what the mesh's Gaussians need
  DualStencilPass compute_;
  CornerLimitPass corners_;
  PatchDraw patches_;
  NormalisedFrame frame_;
  FramedGaussians framed_;  // the mesh's Gaussians in frame_, as uploaded
  StaticTriangles static_triangles_;
  CageLines cage_;
  EllipsoidOverlay ellipsoids_;
  bool ellipsoids_current_ = false;  // whether ellipsoids_ holds framed_
  ShaderProgram cached_, cached_grid_,
      cached_wire_;  // the surface cache's draw (plain, quads' wireframe, triangles' wireframe)
  SurfaceCache cache_;
  StoredVertexEvaluation stored_evaluation_;  // the cache's edits where the tessellation stays
  StoredPatchLevels stored_levels_;           // the levels of the cache's adaptive capture
  PatchTriangleCounts triangle_counts_;       // where the cache finds a patch's triangles in its block
  long long points_generation_ = 0;           // bumped by every compute pass: the cache's key
  GlTexture matcap_ = GlTexture::none();      // made by set_matcap()
  long long tables_id_ = 0;                   // the replanner's id of tables_ (PlanChange), 0 where none gave one
  CornerItems all_corner_items_;              // CornerLimitPass::all_items of tables_, once a pass needed them
  int last_corner_slots_ = 0;
  long long half_size_patches_ = 0;  // a split face's patches (quads), counted when the cache's buffer
                                     // estimate first needs them (−1: not yet)
  int group_limit_ = 0;              // lowered by tests only (DeviceLimitsForTests)
  long long storage_limit_ = 0;
  GpuPassTimer* timer_ = nullptr;
  DrawStatistics last_statistics_;
  std::unique_ptr<QueryRing> cached_statistics_;  // while collecting statistics: a cached draw's vertices
  CacheFrame last_cache_frame_ = CacheFrame::live;
  // What draws_as_last() compares: the revision counts every change of what a draw draws.
  std::uint64_t revision_ = 0;
  struct LastDraw {
    std::uint64_t target = 0, revision = 0;  // the target's serial; 0: none yet
    Camera camera;
    DrawnOptions options;
    bool repeatable = false;  // drawn live, or from a settled cache: the same inputs draw the same
  };
  LastDraw last_draw_;
};

}  // namespace gps
