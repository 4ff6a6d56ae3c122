#include "render/pipeline/corner_limit_pass.h"

#include <glad/gl.h>

#include <algorithm>

#include "core/mesh/mesh_connectivity.h"
#include "core/plans/patch_adjacency.h"
#include "core/support/sorted_indices.h"
#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "render/gl/gpu_layout.h"
#include "shaders/embedded_shaders.h"

namespace gps {

CornerLimitPass::CornerLimitPass()
    : programs_(plan_compute_programs("corner_limits", true, {shaders::corner_limit_comp})),
      leaf_programs_(plan_compute_programs("corner_limits_leaves", true, {shaders::corner_limit_comp},
                                           "#define GPS_LEAVES_ONLY\n")),
      clear_("corner_clear", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::corner_clear_comp}}}) {}

void CornerLimitPass::set_precision(PointPrecision precision) {
  programs_.set_precision(precision);
  leaf_programs_.set_precision(precision, false);  // the same program less a branch: checked above
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
  sort_unique_indices(slots, n * plans.n_patches());
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
  std::vector<int> leaves, exact, zeros;
  leaves.reserve(2 * slots.size());
  zeros.reserve(2 * slots.size());
  for (const int slot : slots) {
    const int patch = slot / n, c = slot - n * patch;
    std::vector<int>& evaluations = holds_extraordinary_node(plans, plans.patch_roots[size_t(patch)]) ? exact : leaves;
    if (holds_midpoint(plans, patch, c))
      evaluations.push_back(kCornerItemOps * slot + gpu::kCornerItemMidpoint);
    else
      zeros.push_back(kCornerItemOps * slot + gpu::kCornerItemClearMidpoint);
    if (evaluates_corner(plans, patch, c))
      evaluations.push_back(kCornerItemOps * slot + gpu::kCornerItemCorner);
    else
      zeros.push_back(kCornerItemOps * slot + gpu::kCornerItemClearCorner);
  }
  const int leaf_evaluations = int(leaves.size());
  const int evaluations = leaf_evaluations + int(exact.size());
  leaves.insert(leaves.end(), exact.begin(), exact.end());
  leaves.insert(leaves.end(), zeros.begin(), zeros.end());
  return {std::move(leaves), leaf_evaluations, evaluations};
}

CornerItems CornerLimitPass::all_items(const PatchPlans& plans) {
  const int n = plans.corners(), n_patches = plans.n_patches();
  // Counted per patch first, so that the items are written in parallel, in slot order within the
  // leaves' and within the others'.
  std::vector<int> first(size_t(n_patches) + 1, 0);
  std::vector<char> exact(static_cast<size_t>(n_patches));
#pragma omp parallel for schedule(static) if (n_patches >= kParallelFaces)
  for (int p = 0; p < n_patches; ++p) {
    exact[size_t(p)] = holds_extraordinary_node(plans, plans.patch_roots[size_t(p)]);
    int count = 0;
    for (int c = 0; c < n; ++c) count += int(holds_midpoint(plans, p, c)) + int(evaluates_corner(plans, p, c));
    first[size_t(p) + 1] = count;
  }
  // The leaves' patches, then the others: the second run's offsets start where the first ends.
  int leaf_evaluations = 0;
  for (int p = 0; p < n_patches; ++p)
    if (!exact[size_t(p)]) leaf_evaluations += first[size_t(p) + 1];
  int leaf_at = 0, exact_at = leaf_evaluations;
  for (int p = 0; p < n_patches; ++p) {
    const int count = first[size_t(p) + 1];
    first[size_t(p) + 1] = 0;
    first[size_t(p)] = exact[size_t(p)] ? exact_at : leaf_at;
    (exact[size_t(p)] ? exact_at : leaf_at) += count;
  }
  std::vector<int> items(static_cast<size_t>(exact_at));
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
  return {std::move(items), leaf_evaluations, evaluations};
}

void CornerLimitPass::run(const PatchPlans& plans, const CornerItems& items, int group_limit) const {
  const int n_items = int(items.size());
  const auto evaluate = [&](const ShaderProgram& program, int from, int to) {
    if (to <= from) return;
    program.set("u_from", from);
    run_compute_pass(program, to - from, true, group_limit);
  };
  evaluate(leaf_programs_(plans.shape), 0, items.leaf_evaluations);
  evaluate(programs_(plans.shape), items.leaf_evaluations, items.evaluations);
  if (n_items > items.evaluations) {
    clear_.set("u_from", items.evaluations);
    run_compute_pass(clear_, n_items - items.evaluations, true, group_limit);
  }
  check_gl_errors("the corner pass");
}

}  // namespace gps
