#pragma once
// The corner pass (shaders/corner_limit_comp.glsl): after the stencils, the limit point, normal and
// node kind at every patch corner its owner evaluates (and at a corner on an infinitely sharp crease,
// the normal of each patch there), which the tessellation stages then read instead of evaluating a
// corner themselves, and the limit point halfway along each patch edge that names its edge's limit
// curve, which the adaptive levels measure (shaders/tess_levels.glsl); over every corner, or over an
// edit's list (PlanBuffers::upload_corner_list). Dispatches split to the device's work-group count
// limit.
#include <vector>

#include "core/plans/patch_plans.h"
#include "render/gl/shape_programs.h"
#include "render/gl/point_precision.h"

namespace gps {

class CornerLimitPass {
public:
  /// Needs a current GL 4.5 context.
  CornerLimitPass();

  /// The pass for points of `precision` from now on (its programs built at the first use).
  void set_precision(PointPrecision precision);

  /// Every corner slot of the plans' patches (buffers bound).
  void run_all(const PatchPlans& plans, int group_limit) const;
  /// The `n_listed` slots of the corner list (buffers bound).
  void run_listed(const PatchPlans& plans, int n_listed, int group_limit) const;
  /// The slots whose values an edit of `patches` can change: the owner slots of their corners and
  /// their own slots (a normal on a crease, the midpoint of the edge that starts there).
  static std::vector<int> edit_slots(const PatchPlans& plans, const std::vector<int>& patches);

private:
  void run(const PatchPlans& plans, int count, bool use_list, int group_limit) const;

  ShapePrograms programs_;
};

}  // namespace gps
