#include "render/pipeline/surface_renderer.h"

#include <glad/gl.h>

#include <utility>

#include "core/plans/patch_adjacency.h"
#include "core/plans/stencil_table.h"
#include "render/pipeline/kept_corner_output.h"
#include "render/gl/gl_context.h"
#include "render/gl/image_texture.h"
#include "render/gl/moved_frame.h"
#include "render/image/matcap.h"
#include "shaders/embedded_shaders.h"

namespace gps {

SurfaceRenderer::SurfaceRenderer()
    : cached_("cached", {{GL_VERTEX_SHADER, {shaders::cache_vert}}, {GL_FRAGMENT_SHADER, {shaders::shade_frag}}}),
      cached_grid_("cached_grid", {{GL_VERTEX_SHADER, {"#define CACHE_GRID\n", shaders::cache_vert}},
                                   {GL_FRAGMENT_SHADER, {shaders::shade_frag}}}),
      cached_wire_("cached_wire", {{GL_VERTEX_SHADER, {shaders::geometry_next, shaders::cache_vert}},
                                   {GL_GEOMETRY_SHADER, {shaders::mesh_geom}},
                                   {GL_FRAGMENT_SHADER, {shaders::shade_frag}}}) {
  set_matcap(make_builtin_matcap("clay"));
  check_gl_errors("creating the renderer");
}

const SurfaceTables& SurfaceRenderer::tables() const { return *tables_; }

void SurfaceRenderer::set_mesh(const CovarianceMesh& mesh, SurfaceTables surface_tables, const NormalisedFrame& frame) {
  set_mesh(mesh, std::move(surface_tables), frame, PlanChange{}, {});
}

void SurfaceRenderer::set_mesh(const CovarianceMesh& mesh, std::shared_ptr<const SurfaceTables> surface_tables,
                               const NormalisedFrame& frame, const PlanChange& change, const std::vector<int>& origin) {
  // The same plans, and every vertex moved by one rotation, scale and translation: the frame moves with them.
  if (change.from != 0 && change.from == tables_id_ && surface_tables->plans.shape == shape() &&
      same_plans(*tables_, *surface_tables, change.kept, origin) && follow_move(mesh)) {
    tables_id_ = change.to;
    return;
  }
  // Refused before anything changes: the renderer keeps drawing the previous mesh.
  // In the same frame, what the unchanged Gaussians gave is carried to where they went.
  const bool carry =
      frame == frame_ && framed_.n_vertices() > 0 && (origin.empty() || origin.size() == mesh.n_vertices());
  // Where the change keeps vertex numbers, only its changed Gaussians are framed and kept, and written
  // into those held once nothing refuses the mesh; else every vertex is framed anew.
  const bool in_place = carry && keeps_vertex_numbers(origin, framed_.n_vertices(), mesh.n_vertices());
  FramedGaussians framed;
  GaussiansChange gaussians;
  std::vector<int> framed_changed;
  if (in_place)
    gaussians = gaussians_change(framed_, mesh, frame, origin);
  else if (carry)
    framed_changed = changed_gaussians(framed_, mesh, frame, origin, framed);
  else
    framed = frame.gaussians_in_frame(mesh);
  const std::vector<int>& changed = in_place ? gaussians.changed : framed_changed;
  const auto take_framed = [&] {
    if (in_place)
      apply_gaussians_change(gaussians, origin, framed_);
    else
      framed_ = std::move(framed);
  };
  ++revision_;
  const bool few_changed = carry && !update_everything(changed.size(), mesh.n_vertices());
  MeshPointPrecision point_precision = in_place ? MeshPointPrecision(point_precision_, gaussians, origin)
                                       : carry  ? MeshPointPrecision(point_precision_, framed, origin, changed)
                                                : MeshPointPrecision(framed);
  PlanBuffers::check_fits(*surface_tables, int(mesh.n_vertices()), int(mesh.n_faces()), storage_limit_,
                          point_precision.precision());
  // The corner pass's output of the kept patches holds where it was computed alike.
  const std::vector<KeptPatches>& kept = change.kept;
  const bool same_precision = point_precision.precision() == buffers_.precision();
  const bool keep = change.from != 0 && change.from == tables_id_ && !kept.empty() && carry && same_precision &&
                    surface_tables->plans.shape == shape() &&
                    kept_runs_fit(kept, n_patches(), surface_tables->plans.n_patches());
  if (keep && same_plans(*tables_, *surface_tables, kept, origin)) {  // the Gaussians alone: followed as an edit
    tables_id_ = change.to;
    take_framed();
    point_precision_ = std::move(point_precision);
    return follow_edit(changed);
  }
  use_point_precision(point_precision.precision());
  point_precision_ = std::move(point_precision);
  const std::shared_ptr<const SurfaceTables> before = std::exchange(tables_, std::move(surface_tables));
  dependents_.reset();
  readers_.reset();
  mesh_shape_ = mesh.shape();
  first_patches_.reset();
  near_patches_listed_ = 0;
  all_corner_items_ = {};
  half_size_patches_ = -1;
  // Kept tables keep the points of the base vertices that did not change, in this frame and precision.
  const PlanBuffers::CarriedPoints carried{origin, changed, change.kept_rows, before->stencils.first_row()};
  buffers_.upload_tables(*tables_, keep ? kept : std::vector<KeptPatches>{}, keep && few_changed ? &carried : nullptr,
                         before.get(), change.from != 0 && change.from == tables_id_ ? &change : nullptr);
  tables_id_ = change.to;
  frame_ = frame;
  patches_.set_frame(frame_);
  cache_.set_frame(frame_);
  take_framed();
  if (few_changed && same_precision)
    buffers_.carry_gaussians(framed_, origin, changed);
  else
    buffers_.upload_gaussians(framed_);
  ellipsoids_current_ = false;           // uploaded when first drawn: most frames draw none
  // The overlays too are drawn in the frame; the cache projects the cage with the frame's view-projection.
  cache_.set_cage(mesh, framed_, keep);
  cage_.set_mesh(mesh, cache_.cage_positions());
  if (keep)
    run_compute_kept(mesh, *before, changed, change, origin, few_changed);
  else
    run_compute(nullptr);
}

// Kept in the mesh's frame, as the patches are: world coordinates far from the origin lose their
// digits in float.
void SurfaceRenderer::set_triangles(const TriangleMesh& triangles, const Vec3& origin) {
  TriangleMesh framed = triangles;
  // The origin and the frame's centre lie near each other for a mesh far away: their difference first.
  const Vec3 centre = Vec3(frame_.centre.x, frame_.centre.y, frame_.centre.z) - origin;
  for (Vec3& p : framed.positions) p = (p - centre) / frame_.unit;
  if (frame_.turned())
    for (Vec3& p : framed.positions) {
      const glm::dvec3 q = glm::transpose(frame_.rotation) * glm::dvec3(p.x(), p.y(), p.z());
      p = Vec3(q.x, q.y, q.z);
    }
  static_triangles_.set(framed);
  ++revision_;
}

void SurfaceRenderer::use_point_precision(PointPrecision precision) {
  const PointPrecision previous = buffers_.precision();
  try {
    compute_.set_precision(precision);
    corners_.set_precision(precision);
    patches_.set_precision(precision);
    stored_evaluation_.set_precision(precision);
    stored_levels_.set_precision(precision);
    triangle_counts_.set_precision(precision);
  } catch (...) {
    use_point_precision(previous);  // built already: no refusal
    throw;
  }
  buffers_.set_precision(precision);
}

void SurfaceRenderer::update_vertices(const CovarianceMesh& mesh, const std::vector<int>& changed) {
  if (changed.size() == framed_.n_vertices() && follow_move(mesh)) return;
  // The frame stays that of set_mesh, so that the vertices not uploaded again still fit. Of those
  // listed, only the ones that changed (a tool lists what it may move: G's first frame moves nothing).
  const std::vector<int> moved = frame_.to_frame(mesh, changed, framed_);
  if (moved.empty()) return;
  ++revision_;
  point_precision_.update(framed_, moved);
  follow_edit(moved);
}

bool SurfaceRenderer::follow_move(const CovarianceMesh& mesh) {
  // The static triangles lie in the frame too, but are not the mesh's: they would move with it.
  if (static_triangles_.drawn()) return false;
  FramedGaussians moved;
  const std::optional<NormalisedFrame> to = moved_frame(frame_, framed_, mesh, moved);
  if (!to) return false;
  framed_ = std::move(moved);  // within rounding of those uploaded, and what later edits are framed against
  frame_ = *to;
  patches_.set_frame(frame_);
  cache_.set_frame(frame_);
  ++revision_;
  return true;
}

void SurfaceRenderer::follow_edit(const std::vector<int>& changed) {
  cache_.update_cage(framed_, changed);
  const bool new_precision = point_precision_.precision() != buffers_.precision();
  if (new_precision) {  // the points' buffer in the new precision
    use_point_precision(point_precision_.precision());
    buffers_.upload_tables(tables());
  }
  // Most of the mesh (select all, drag), or a new precision: whole buffers, one call each.
  if (new_precision || update_everything(changed.size(), framed_.n_vertices())) {
    buffers_.upload_gaussians(framed_);
    ellipsoids_current_ = false;
    cage_.upload_positions(cache_.cage_positions());
    run_compute(nullptr, true);
    return;
  }
  buffers_.update_gaussians(framed_, changed);
  cage_.update_positions(cache_.cage_positions(), changed);
  if (ellipsoids_current_) ellipsoids_.upload(framed_, &changed);
  run_compute(&changed);
}

void SurfaceRenderer::set_matcap(const Image& m) {
  matcap_ = image_texture(m);  // its storage is immutable: a new texture per MatCap
  ++revision_;
}

void SurfaceRenderer::set_collect_statistics(bool collect) {
  patches_.set_collect_statistics(collect);
  if (!collect || !GLAD_GL_ARB_pipeline_statistics_query)
    cached_statistics_.reset();
  else if (!cached_statistics_)
    cached_statistics_ = std::make_unique<QueryRing>(std::vector<unsigned>{GL_VERTEX_SHADER_INVOCATIONS_ARB}, 4);
}

DrawStatistics SurfaceRenderer::last_statistics() {
  last_statistics_.cached = last_cache_frame_ == CacheFrame::stored;
  if (last_cache_frame_ != CacheFrame::live) {
    last_statistics_.triangles = cache_.triangles();
    // A frame drawn as it was captured ran its evaluation block by block: not counted.
    last_statistics_.vertices = -1;
    if (last_statistics_.cached && GLAD_GL_ARB_pipeline_statistics_query) {
      last_statistics_.vertices = 0;  // none finished yet, or not collecting
      if (cached_statistics_)
        if (const auto& counts = cached_statistics_->latest()) last_statistics_.vertices = (long long)(*counts)[0];
    }
  } else {
    patches_.latest_statistics(last_statistics_);
  }
  last_statistics_.patches = n_patches();
  return last_statistics_;
}

void SurfaceRenderer::draw(const RenderTarget& target, const Camera& camera, const DrawOptions& o) {
  const float aspect = float(target.width()) / float(target.height());
  CacheFrame cache_frame = CacheFrame::live;
  {
    const GpuPassScope pass(timer_, "surface");
    const bool use_cache = !o.static_triangles && o.surface_cache && !hides_patches(o);
    buffers_.bind();
    // The cache's compute passes before the clear: on llvmpipe one after it splits the frame in two
    // (the cleared target written out, then read back for the draw).
    const bool cache_matches = use_cache && prepare_cache(camera, o, aspect, target.width(), target.height());
    target.bind();
    const float clear_color[4] = {o.background.r, o.background.g, o.background.b, 1.0f};
    const float clear_zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, clear_color);
    glClearBufferfv(GL_COLOR, 1, clear_zero);
    glClearBufferfv(GL_COLOR, 2, clear_zero);
    const float far_depth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glBindTextureUnit(0, matcap_);
    cache_frame = !use_cache                      ? CacheFrame::live
                  : !cache_matches                ? capture_cache(camera, o, aspect, target.width(), target.height())
                  : cache_.has_stored_triangles() ? CacheFrame::stored
                                                  : CacheFrame::live;  // refused: past the memory limit
    const bool cached = cache_frame == CacheFrame::stored;
    last_cache_frame_ = cache_frame;
    if (cache_frame != CacheFrame::drawn) {  // else drawn as it was captured
      // The geometry shader only where a triangle wireframe is wanted: the static floor of the benchmark stays plain.
      const bool triangle_wire = o.wireframe && shape() == PatchShape::triangle;
      const bool grid = cached && draws_grid(o);
      const ShaderProgram& program = cached                ? (triangle_wire ? cached_wire_
                                                              : grid        ? cached_grid_
                                                                            : cached_)
                                     : !o.static_triangles ? patches_.frame_program(shape(), o)
                                                           : static_triangles_.program(o.wireframe);
      set_frame_uniforms(program, camera, o, aspect, target.width(), target.height(), frame_);
      program.use();
      if (o.static_triangles)
        static_triangles_.draw();
      else if (cached)
        draw_cache(grid);
      else
        patches_.draw(shape(), program, o, n_patches());
    }
  }
  if (o.ellipsoids && framed_.n_vertices() > 0) {
    const GpuPassScope pass(timer_, "ellipsoids");
    if (!ellipsoids_current_) ellipsoids_.upload(framed_, nullptr);
    ellipsoids_current_ = true;
    target.set_colour_only(true);
    ellipsoids_.draw(frame_view_projection(camera, aspect, frame_), o.sigma_scale, o.ellipsoid_vertices);
    target.set_colour_only(false);
  }
  if (o.mesh_lines && !cage_.empty()) {
    const GpuPassScope pass(timer_, "mesh lines");
    cage_.draw(target, frame_view_projection(camera, aspect, frame_), o.hidden_edges);
  }
  glBindVertexArray(0);
  check_gl_errors("drawing");
  last_draw_.target = target.serial();
  last_draw_.revision = revision_;
  last_draw_.camera = camera;
  last_draw_.options.record(o);
  // A frame drawn as it was captured is followed by one drawn from the cache.
  last_draw_.repeatable = cache_frame == CacheFrame::live || (cache_frame == CacheFrame::stored && cache_.settled());
}

bool SurfaceRenderer::draws_as_last(const RenderTarget& target, const Camera& camera, const DrawOptions& o) const {
  return last_draw_.repeatable && last_draw_.target == target.serial() && last_draw_.revision == revision_ &&
         last_draw_.camera == camera && last_draw_.options.same(o);
}

std::vector<TessellatedVertex> SurfaceRenderer::capture_vertices(const Camera& camera, const DrawOptions& o, int width,
                                                                 int height, int first_patch, int n_patches) {
  buffers_.bind();
  return patches_.capture_vertices(shape(), camera, o, width, height, this->n_patches(), first_patch, n_patches);
}

std::vector<TessellatedVertex> SurfaceRenderer::capture_frame_vertices(const Camera& camera, const DrawOptions& o,
                                                                       int width, int height, int first_patch,
                                                                       int n_patches) {
  buffers_.bind();
  return patches_.capture_frame_vertices(shape(), camera, o, width, height, this->n_patches(), first_patch, n_patches);
}

std::vector<glm::dvec3> SurfaceRenderer::corner_limit_points() const {
  const PatchPlans& plans = tables().plans;
  const int corners = plans.corners();
  std::vector<glm::dvec3> points;
  buffers_.read_corner_limits([&](const float* limits) {
    for (int p = 0; p < n_patches(); ++p)
      for (int c = 0; c < corners; ++c) {
        const CornerOwner owner = corner_owner(plans, p, c);
        if (owner.patch != p || owner.corner != c) continue;  // its owner's slot holds it
        const float* limit = &limits[size_t(8 * (corners * p + c))];
        points.emplace_back(limit[0], limit[1], limit[2]);
      }
  });
  return points;
}

}  // namespace gps
