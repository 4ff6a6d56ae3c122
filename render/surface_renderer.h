#pragma once
// The GPU pipeline of DESIGN.md §2: plans and stencils uploaded once per topology; per edit a
// compute pass maps changed vertices to 9D and applies the stencils; per frame GL_PATCHES with
// tessellation shaders evaluate the limit surface, shaded by MatCap.
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "core/covariance_mesh.h"
#include "core/planned_surface.h"
#include "core/triangle_mesh.h"
#include "view/camera.h"
#include "render/ellipsoid_overlay.h"
#include "render/gpu_layout.h"
#include "render/gpu_pass_timer.h"
#include "render/image_io.h"
#include "render/query_ring.h"
#include "render/render_target.h"
#include "render/shader_program.h"
#include "render/surface_cache.h"

namespace gps {

enum class ShadingMode { matcap = 0, normals = 1, flat = 2 };

/// The opacity of the base mesh's lines where the surface hides them (those in front are opaque).
constexpr float kHiddenCageAlpha = 0.25f;

struct DrawOptions {
  float level = 8.0f;      // uniform tessellation level 1..64
  float pixels = 0.0f;     // > 0: adaptive levels, target edge length in pixels
  ShadingMode mode = ShadingMode::matcap;
  bool wireframe = false;  // tessellation wireframe over the shading
  bool mesh_lines = false; // the base mesh as thin grey lines, faint (kHiddenCageAlpha) where behind the surface
  bool ellipsoids = false; // covariance ellipsoids
  const std::vector<int>* ellipsoid_vertices = nullptr;  // set: only these vertices' ellipsoids (ascending)
  float sigma_scale = 1.0f;
  glm::vec3 background{1.0f, 1.0f, 1.0f};
  bool static_triangles = false;  // draw the triangles of set_triangles() instead of the patches
  bool surface_cache = true;      // redraw stored triangles while points and levels stay (render/surface_cache.h)
  bool flag_back_faces = false;   // crack checks: draw back faces in pure magenta
  bool debug_mismatch = false;    // tests only: give neighbouring patches different edge levels
};

/// One vertex the tessellator produced: patch, (u, v), position and normal (transform feedback).
/// A vertex on a patch edge is evaluated from the canonical patch of that point
/// (shaders/canonical_edge.glsl): `evaluated` is the patch and (u, v) that computed it.
struct TessellatedVertex {
  float patch, u, v;
  float position[3];
  float normal[3];
  float evaluated[3];
};

/// What the patch draws produced (pipeline-statistics queries; see SurfaceRenderer::set_collect_statistics).
struct DrawStatistics {
  long long triangles = 0;  // primitives the tessellator generated
  long long vertices = 0;   // tessellation evaluation shader invocations; -1 without ARB_pipeline_statistics_query
  int patches = 0;          // patches of the plan
  bool cached = false;      // drawn from the surface cache: `triangles` are the stored ones, nothing was evaluated
};

class SurfaceRenderer {
public:
  /// Needs a current GL 4.5 context.
  SurfaceRenderer();
  ~SurfaceRenderer();
  SurfaceRenderer(const SurfaceRenderer&) = delete;
  SurfaceRenderer& operator=(const SurfaceRenderer&) = delete;

  /// New topology: builds plans and stencils (CPU) under the scheme `options` give for the mesh
  /// (Loop for triangles only, else Catmull-Clark) and uploads everything, then a full compute pass.
  void set_mesh(const CovarianceMesh& mesh, const PlanOptions& options);
  /// The same with the default options: the scheme that fits the mesh, exact plans.
  void set_mesh(const CovarianceMesh& mesh) { set_mesh(mesh, PlanOptions{}); }
  /// An edit: uploads the changed vertices and re-runs the compute passes on what depends on them
  /// (past an eighth of the vertices: whole buffers and the full passes, fewer calls).
  void update_vertices(const CovarianceMesh& mesh, const std::vector<int>& changed);
  /// The compute passes over every vertex and stencil row (as after set_mesh), for benchmarks.
  void recompute_all() { run_compute(nullptr); }
  /// Triangles to draw with DrawOptions::static_triangles (CPU tessellation, reference subdivision).
  void set_triangles(const TriangleMesh& triangles);
  void set_matcap(const Image& matcap);

  void draw(const RenderTarget& target, const Camera& camera, const DrawOptions& options);
  /// The vertices the tessellator generates for `options` (no rasterisation), of the patches
  /// [first_patch, first_patch + n_patches) (n_patches < 0: to the last).
  std::vector<TessellatedVertex> capture_vertices(const Camera& camera, const DrawOptions& options, float aspect,
                                                  int first_patch = 0, int n_patches = -1);

  /// The stored triangles of DrawOptions::surface_cache (its capture count, hysteresis, limit).
  SurfaceCache& surface_cache() { return cache_; }
  const SurfaceCache& surface_cache() const { return cache_; }

  /// Times the compute passes ("9D + stencils") and each drawn layer ("surface", "ellipsoids",
  /// "mesh lines") into `timer`; nullptr (the default) times nothing.
  void set_pass_timer(GpuPassTimer* timer) { timer_ = timer; }
  /// Counts triangles and vertices of each patch draw (off by default: headless renders pay nothing).
  void set_collect_statistics(bool collect);
  /// The figures of the newest patch draw whose queries finished: drawing every frame, they lag a
  /// frame or two (the queries are never waited for). Zero counts before any finished.
  DrawStatistics last_statistics();

  const PlanTables& tables() const { return tables_; }
  /// The plan points as the compute passes left them (12 floats each: q in three vec4).
  std::vector<float> read_points() const;
  /// GPU memory held by the pipeline's buffers, in bytes.
  size_t buffer_bytes() const;
  /// Lowers the device's limits on work groups per compute dispatch and on storage block bytes
  /// (0: the device's own), so that tests reach the dispatch split and the size refusal with meshes
  /// of test size. Applies from the next set_mesh / update_vertices.
  void lower_device_limits(int max_groups, long long max_storage_bytes) {
    group_limit_ = max_groups;
    storage_limit_ = max_storage_bytes;
  }

private:
  void upload_gaussians(const CovarianceMesh& mesh);
  void upload_line_positions(const CovarianceMesh& mesh);
  void run_compute(const std::vector<int>* changed);
  bool draw_from_cache(const Camera& camera, const DrawOptions& options, float aspect, int width, int height);
  void draw_patches(const ShaderProgram& program, const DrawOptions& options, int first_patch = 0, int n_patches = -1) const;
  void set_frame_uniforms(const ShaderProgram& p, const Camera& camera, const DrawOptions& options, float aspect, int width,
                          int height) const;

  PlanTables tables_;
  StencilDependents dependents_;  // which stencil rows read each base vertex
  const ShaderProgram& patch_program_for(bool feedback, bool wireframe) const;

  ShaderProgram dual_map_, stencil_, patches_, feedback_, triangle_patches_, triangle_feedback_, triangle_wire_, triangles_, triangles_wire_, lines_;
  ShaderProgram capture_, triangle_capture_, cached_, cached_wire_;  // the surface cache's capture and draw
  SurfaceCache cache_;
  long long points_generation_ = 0;  // bumped by every compute pass: the cache's key
  EllipsoidOverlay ellipsoids_;
  unsigned buffers_[gpu::kBindingCount] = {};
  size_t buffer_sizes_[gpu::kBindingCount] = {};
  unsigned empty_vao_ = 0, triangle_vao_ = 0, triangle_vbo_ = 0, triangle_ibo_ = 0;
  unsigned lines_vao_ = 0, lines_vbo_ = 0, lines_ibo_ = 0;  // base vertex positions, edges as index pairs
  int triangle_count_ = 0, line_index_count_ = 0;
  unsigned matcap_ = 0;
  int n_base_ = 0;
  int group_limit_ = 0;             // lower_device_limits
  long long storage_limit_ = 0;
  GpuPassTimer* timer_ = nullptr;
  std::unique_ptr<QueryRing> statistics_;  // set while collecting statistics
  DrawStatistics last_statistics_;
  bool last_frame_cached_ = false;
};

}  // namespace gps
