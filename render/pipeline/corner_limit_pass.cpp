#include "render/pipeline/corner_limit_pass.h"

#include <glad/gl.h>

#include <algorithm>

#include "core/mesh/mesh_connectivity.h"
#include "core/plans/patch_adjacency.h"
#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "render/gl/gpu_layout.h"
#include "shaders/embedded_shaders.h"

namespace gps {

CornerLimitPass::CornerLimitPass()
    : programs_(plan_compute_programs("corner_limits", true, {shaders::corner_limit_comp})),
      clear_("corner_clear", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::corner_clear_comp}}}) {}

void CornerLimitPass::set_precision(PointPrecision precision) { programs_.set_precision(precision); }

std::vector<int> CornerLimitPass::edit_slots(const PatchPlans& plans, const std::vector<int>& patches) {
  const int n = plans.corners();
  std::vector<int> slots;
  slots.reserve(2 * patches.size() * size_t(n));
  for (const int p : patches)
    for (int c = 0; c < n; ++c) {
      const CornerOwner owner = corner_owner(plans, p, c);
      slots.push_back(n * owner.patch + owner.corner);
      slots.push_back(n * p + c);  // its own normal on a crease; the midpoint of its edge
    }
  std::sort(slots.begin(), slots.end());
  slots.erase(std::unique(slots.begin(), slots.end()), slots.end());
  return slots;
}

namespace {

using gpu::kCornerItemOps;

// Whether slot n·patch + c holds the midpoint of the edge that starts there: where that edge names its
// limit curve (its corner: evaluates_corner).
bool holds_midpoint(const PatchPlans& plans, int patch, int c) {
  return curve_edge(plans, patch, c) == PatchEdgeSlot{patch, c};
}

}  // namespace

CornerItems CornerLimitPass::slot_items(const PatchPlans& plans, const std::vector<int>& slots) {
  const int n = plans.corners();
  std::vector<int> items, zeros;
  items.reserve(2 * slots.size());
  zeros.reserve(2 * slots.size());
  for (const int slot : slots) {
    const int patch = slot / n, c = slot - n * patch;
    if (holds_midpoint(plans, patch, c))
      items.push_back(kCornerItemOps * slot + gpu::kCornerItemMidpoint);
    else
      zeros.push_back(kCornerItemOps * slot + gpu::kCornerItemClearMidpoint);
    if (evaluates_corner(plans, patch, c))
      items.push_back(kCornerItemOps * slot + gpu::kCornerItemCorner);
    else
      zeros.push_back(kCornerItemOps * slot + gpu::kCornerItemClearCorner);
  }
  const int evaluations = int(items.size());
  items.insert(items.end(), zeros.begin(), zeros.end());
  return {std::move(items), evaluations};
}

CornerItems CornerLimitPass::all_items(const PatchPlans& plans) {
  const int n = plans.corners(), n_patches = plans.n_patches();
  // Counted per patch first, so that the items are written in parallel, in slot order.
  std::vector<int> first(size_t(n_patches) + 1, 0);
#pragma omp parallel for schedule(static) if (n_patches >= kParallelFaces)
  for (int p = 0; p < n_patches; ++p) {
    int count = 0;
    for (int c = 0; c < n; ++c) count += int(holds_midpoint(plans, p, c)) + int(evaluates_corner(plans, p, c));
    first[size_t(p) + 1] = count;
  }
  for (int p = 0; p < n_patches; ++p) first[size_t(p) + 1] += first[size_t(p)];
  std::vector<int> items(size_t(first.back()));
#pragma omp parallel for schedule(static) if (n_patches >= kParallelFaces)
  for (int p = 0; p < n_patches; ++p) {
    int at = first[size_t(p)];
    for (int c = 0; c < n; ++c) {
      const int slot = n * p + c;
      if (holds_midpoint(plans, p, c)) items[size_t(at++)] = kCornerItemOps * slot + gpu::kCornerItemMidpoint;
      if (evaluates_corner(plans, p, c)) items[size_t(at++)] = kCornerItemOps * slot + gpu::kCornerItemCorner;
    }
  }
  const int evaluations = int(items.size());
  return {std::move(items), evaluations};
}

void CornerLimitPass::run(const PatchPlans& plans, const CornerItems& items, int group_limit) const {
  const int n_items = int(items.size());
  if (items.evaluations > 0) run_compute_pass(programs_(plans.shape), items.evaluations, true, group_limit);
  if (n_items > items.evaluations) {
    clear_.set("u_from", items.evaluations);
    run_compute_pass(clear_, n_items - items.evaluations, true, group_limit);
  }
  check_gl_errors("the corner pass");
}

}  // namespace gps
