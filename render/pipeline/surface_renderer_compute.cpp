// The renderer's compute passes (render/pipeline/surface_renderer.h): after an edit, a change of
// topology or a whole upload, the 9D points, the stencil rows and the corner pass, and what the
// surface cache is told of them.
#include <glad/gl.h>

#include "core/plans/stencil_table.h"
#include "render/pipeline/kept_corner_output.h"
#include "render/pipeline/kept_surface_triangles.h"
#include "render/pipeline/surface_renderer.h"

namespace gps {

void SurfaceRenderer::run_compute(const std::vector<int>* changed, bool edit) {
  const GpuPassScope pass(timer_, "9D + stencils");
  ++points_generation_;
  ++revision_;
  const PatchPlans& plans = tables().plans;
  if (changed) {
    const std::vector<int> rows = rows_reading(dependents_, *changed);
    buffers_.upload_edit(*changed, rows);
    const std::vector<int> patches = changed_patches(*changed, rows);
    const std::vector<int> corners = CornerLimitPass::edit_slots(plans, patches);
    const std::vector<int> items = CornerLimitPass::slot_items(plans, corners);
    buffers_.upload_corner_list(items);
    buffers_.bind();
    compute_.run_listed(tables().stencils, int(changed->size()), int(rows.size()), group_limit_);
    corners_.run(plans, int(items.size()), group_limit_);
    last_corner_slots_ = int(corners.size());
    cache_.points_changed(points_generation_, &patches);
    return;
  }
  if (all_corner_items_.empty()) all_corner_items_ = CornerLimitPass::all_items(plans);
  buffers_.upload_corner_list(all_corner_items_);
  buffers_.clear_corner_pass(plans);
  buffers_.bind();
  compute_.run_all(tables().stencils, group_limit_);
  corners_.run(plans, int(all_corner_items_.size()), group_limit_);
  last_corner_slots_ = plans.corners() * plans.n_patches();
  if (edit)
    cache_.all_points_changed(points_generation_);
  else
    cache_.points_changed(points_generation_, nullptr);
}

void SurfaceRenderer::run_compute_kept(const SurfaceTables& before, const std::vector<int>& changed,
                                       const PlanChange& change, const std::vector<int>& origin, bool points_carried) {
  const GpuPassScope pass(timer_, "9D + stencils");
  ++points_generation_;
  const PatchPlans& plans = tables().plans;
  const std::vector<int> patches = stale_corner_patches(before, tables(), dependents_, changed, change, origin);
  const std::vector<int> corners = CornerLimitPass::edit_slots(plans, patches);
  const std::vector<int> items = CornerLimitPass::slot_items(plans, corners);
  buffers_.upload_corner_list(items);
  if (points_carried) buffers_.upload_edit(changed, {});
  buffers_.bind();
  if (points_carried)
    compute_.run_listed_vertices(tables().stencils, int(changed.size()), group_limit_);
  else
    compute_.run_all(tables().stencils, group_limit_);
  corners_.run(plans, int(items.size()), group_limit_);
  last_corner_slots_ = int(corners.size());
  // The cache keeps the triangles of the patches kept with all they read, and their recorded levels.
  if (!cache_.has_stored_triangles()) return cache_.points_changed(points_generation_, nullptr);
  const KeptTriangles triangles = kept_triangles(plans, before.plans.n_patches(), change.kept, patches);
  stored_levels_.follow(
      n_patches(), cache_.topology_changed(points_generation_, n_patches(), triangles.new_number, triangles.changed));
}

std::vector<int> SurfaceRenderer::changed_patches(const std::vector<int>& changed, const std::vector<int>& rows) {
  const StencilTable& stencils = tables().stencils;
  if (!readers_) readers_ = std::make_unique<const PatchReaders>(tables().plans, stencils.n_points());
  std::vector<int> points = changed;
  for (const int r : rows) points.push_back(stencils.first_row() + r);
  return readers_->patches_changed_by(points);
}

}  // namespace gps
