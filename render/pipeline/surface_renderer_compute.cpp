// The renderer's compute passes (render/pipeline/surface_renderer.h): after an edit, a change of
// topology or a whole upload, the 9D points, the stencil rows and the corner pass, and what the
// surface cache is told of them.
#include <glad/gl.h>

#include <algorithm>

#include "core/plans/patch_faces.h"
#include "core/plans/stencil_table.h"
#include "render/pipeline/kept_corner_output.h"
#include "render/pipeline/kept_surface_triangles.h"
#include "render/pipeline/surface_renderer.h"

namespace gps {

void SurfaceRenderer::run_compute(const std::vector<int>* changed, bool edit) {
  ++points_generation_;
  ++revision_;
  const PatchPlans& plans = tables().plans;
  if (changed) {
    const std::vector<int> rows = rows_reading(dependents(), *changed);
    buffers_.upload_edit(*changed, rows);
    const std::vector<int> patches = changed_patches(*changed, rows);
    const std::vector<int> corners = CornerLimitPass::edit_slots(plans, patches);
    const CornerItems items = CornerLimitPass::slot_items(plans, corners);
    buffers_.upload_corner_list(items.items);
    buffers_.bind();
    {
      const GpuPassScope pass(timer_, "9D + stencils", GpuPassTimer::Work::dispatches);
      compute_.run_listed(tables().stencils, int(changed->size()), int(rows.size()), group_limit_);
      corners_.run(plans, items, group_limit_);
    }
    last_corner_slots_ = int(corners.size());
    cache_.points_changed(points_generation_, &patches);
    return;
  }
  if (all_corner_items_.items.empty()) all_corner_items_ = CornerLimitPass::all_items(plans);
  buffers_.upload_corner_list(all_corner_items_.items);
  buffers_.clear_corner_pass(plans);
  buffers_.bind();
  {
    const GpuPassScope pass(timer_, "9D + stencils", GpuPassTimer::Work::dispatches);
    compute_.run_all(tables().stencils, group_limit_);
    corners_.run(plans, all_corner_items_, group_limit_);
  }
  last_corner_slots_ = plans.corners() * plans.n_patches();
  if (edit)
    cache_.all_points_changed(points_generation_);
  else
    cache_.points_changed(points_generation_, nullptr);
}

void SurfaceRenderer::run_compute_kept(const CovarianceMesh& mesh, const SurfaceTables& before,
                                       const std::vector<int>& changed, const PlanChange& change,
                                       const std::vector<int>& origin, bool points_carried) {
  ++points_generation_;
  const PatchPlans& plans = tables().plans;
  const std::vector<int> patches = stale_corner_patches(
      before, tables(), mesh, face_first_patches(), [this]() -> const StencilDependents& { return dependents(); },
      changed, change, origin);
  const std::vector<int> corners = CornerLimitPass::edit_slots(plans, patches);
  const CornerItems items = CornerLimitPass::slot_items(plans, corners);
  buffers_.upload_corner_list(items.items);
  const StencilTable& stencils = tables().stencils;
  const std::vector<int> rows = points_carried ? rows_not_carried(before, changed, change, origin) : std::vector<int>{};
  const bool listed_rows = points_carried && !update_everything(rows.size(), size_t(stencils.n_rows()));
  if (points_carried) buffers_.upload_edit(changed, listed_rows ? rows : std::vector<int>{});
  buffers_.bind();
  {
    const GpuPassScope pass(timer_, "9D + stencils", GpuPassTimer::Work::dispatches);
    if (listed_rows)
      compute_.run_listed(stencils, int(changed.size()), int(rows.size()), group_limit_);
    else if (points_carried)
      compute_.run_listed_vertices(stencils, int(changed.size()), group_limit_);
    else
      compute_.run_all(stencils, group_limit_);
    corners_.run(plans, items, group_limit_);
  }
  last_corner_slots_ = int(corners.size());
  // The cache keeps the triangles of the patches kept with all they read, and their recorded levels.
  if (!cache_.has_stored_triangles()) return cache_.points_changed(points_generation_, nullptr);
  const KeptTriangles triangles =
      kept_triangles(mesh, plans, face_first_patches(), before.plans.n_patches(), change.kept, patches);
  stored_levels_.follow(
      n_patches(), cache_.topology_changed(points_generation_, n_patches(), triangles.new_number, triangles.changed));
}

std::vector<int> SurfaceRenderer::rows_not_carried(const SurfaceTables& before, const std::vector<int>& changed,
                                                   const PlanChange& change, const std::vector<int>& origin) {
  const int n_rows = tables().stencils.n_rows();
  std::vector<char> compute(size_t(n_rows), 1);
  for (const KeptStencilRows& run : change.kept_rows) std::fill_n(compute.begin() + run.first, run.count, 0);
  // A kept row reads vertices that were there before: those whose Gaussians changed make it stale.
  const bool old_changed = std::any_of(changed.begin(), changed.end(), [&](int v) {
    return size_t(origin.empty() ? v : origin[size_t(v)]) < size_t(before.stencils.n_base);
  });
  if (old_changed)
    for (const int r : rows_reading(dependents(), changed)) compute[size_t(r)] = 1;
  std::vector<int> rows;
  for (int r = 0; r < n_rows; ++r)
    if (compute[size_t(r)]) rows.push_back(r);
  return rows;
}

const std::vector<int>& SurfaceRenderer::face_first_patches() {
  if (!first_patches_) first_patches_ = first_patches(mesh_shape_->topology, tables().plans);
  return *first_patches_;
}

const StencilDependents& SurfaceRenderer::dependents() {
  if (!dependents_) dependents_ = stencil_dependents(tables().stencils);
  return *dependents_;
}

std::vector<int> SurfaceRenderer::changed_patches(const std::vector<int>& changed, const std::vector<int>& rows) {
  const StencilTable& stencils = tables().stencils;
  // A few vertices (a drag, the move after an extrusion) are looked up around them in the mesh; more,
  // or once those lookups have listed as many patches as the surface has, in an index over every patch,
  // built once per topology.
  if (!readers_ && changed.size() * kNearEditDivisor < size_t(stencils.n_base) &&
      near_patches_listed_ < size_t(n_patches())) {
    std::vector<int> patches = patches_changed_near(mesh_shape_->topology, mesh_shape_->connectivity, tables().plans,
                                                    face_first_patches(), stencils.first_row(), changed, rows);
    near_patches_listed_ += patches.size();
    return patches;
  }
  if (!readers_) readers_ = std::make_unique<const PatchReaders>(tables().plans, stencils.n_points());
  std::vector<int> points = changed;
  for (const int r : rows) points.push_back(stencils.first_row() + r);
  return readers_->patches_changed_by(points);
}

}  // namespace gps
