#pragma once
// The corner pass (shaders/corner_limit_comp.glsl): after the stencils, the limit point, normal and
// node kind at every patch corner its owner evaluates (and at a corner on an infinitely sharp crease,
// the normal of each patch there), which the tessellation stages then read instead of evaluating a
// corner themselves, and the limit point halfway along each patch edge that names its edge's limit
// curve, which the adaptive levels measure (shaders/tess_levels.glsl). It runs over a list of items
// (PlanBuffers::upload_corner_list), one evaluation or zeroed value each, which its builder here
// finds on the CPU: a slot's two values are then evaluated by two invocations, where one invocation
// looping over both made each SIMD batch run both. The evaluations come first; the zeroes after them
// are written by a program of their own (shaders/corner_clear_comp.glsl). The evaluations of patches
// whose plans hold no extraordinary node come first, for a program built without the exact node's
// branch, which a software driver otherwise runs in every batch. Dispatches split to the device's
// work-group count limit.
#include <vector>

#include "core/plans/patch_plans.h"
#include "render/gl/shape_programs.h"
#include "render/gl/point_precision.h"

namespace gps {

/// The corner pass's items (gpu_layout.h, kCornerItemOps): its evaluations, those on plans without an
/// extraordinary node first, then its zeroes.
struct CornerItems {
  std::vector<int> items;
  int leaf_evaluations = 0;  // the first items: evaluations on plans without an extraordinary node
  int evaluations = 0;
  size_t size() const { return items.size(); }
};

class CornerLimitPass {
public:
  /// Needs a current GL 4.5 context.
  CornerLimitPass();

  /// The pass for points of `precision` from now on (its programs built at the first use).
  void set_precision(PointPrecision precision);

  /// Runs `items`, uploaded as the corner list (buffers bound): its evaluations, then its zeroes.
  void run(const PatchPlans& plans, const CornerItems& items, int group_limit) const;
  /// The slots whose values an edit of `patches` can change: the owner slots of their corners and
  /// their own slots (a normal on a crease, the midpoint of the edge that starts there).
  static std::vector<int> edit_slots(const PatchPlans& plans, const std::vector<int>& patches);
  /// The items of `slots`: each slot's evaluations, and a zero for the values it does not hold.
  static CornerItems slot_items(const PatchPlans& plans, const std::vector<int>& slots);
  /// The evaluations of every corner slot of the plans' patches, for outputs cleared before.
  static CornerItems all_items(const PatchPlans& plans);

private:
  ShapePrograms programs_;
  ShapePrograms leaf_programs_;  // for the leaf evaluations: built without the extraordinary branch
  ShaderProgram clear_;  // the zeroes: the same for every shape and precision
};

}  // namespace gps
