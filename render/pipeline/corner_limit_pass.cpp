#include "render/pipeline/corner_limit_pass.h"

#include <glad/gl.h>

#include <algorithm>

#include "core/plans/patch_adjacency.h"
#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

CornerLimitPass::CornerLimitPass()
    : programs_(plan_compute_programs("corner_limits", true, {shaders::corner_limit_comp})) {}

void CornerLimitPass::set_precision(PointPrecision precision) { programs_.set_precision(precision); }

void CornerLimitPass::run_all(const PatchPlans& plans, int group_limit) const {
  run(plans, plans.corners() * plans.n_patches(), false, group_limit);
}

void CornerLimitPass::run_listed(const PatchPlans& plans, int n_listed, int group_limit) const {
  run(plans, n_listed, true, group_limit);
}

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

void CornerLimitPass::run(const PatchPlans& plans, int count, bool use_list, int group_limit) const {
  if (count <= 0) return;
  run_compute_pass(programs_(plans.shape), count, use_list, group_limit);
  check_gl_errors("the corner pass");
}

}  // namespace gps
