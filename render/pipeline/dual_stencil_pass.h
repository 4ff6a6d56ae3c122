#pragma once
// The compute passes of an edit (docs/design.md §2): base vertices' Gaussians to 9D points
// (shaders/dual_map_comp.glsl), then the stencil rows (shaders/stencil_comp.glsl), over everything
// or over the lists PlanBuffers::upload_edit left; dispatches split to the device's work-group
// count limit (render/gl/compute_limits.h).
#include "render/pipeline/plan_buffers.h"
#include "render/gl/point_precision.h"
#include "render/gl/shader_program.h"

namespace gps {

class DualStencilPass {
public:
  /// Needs a current GL 4.5 context.
  DualStencilPass();

  /// The passes for points of `precision` from now on (its programs built at the first use).
  void set_precision(PointPrecision precision);

  /// Every base vertex and stencil row of `stencils` (buffers bound).
  void run_all(const StencilTable& stencils, int group_limit) const {
    run(stencils.first_row(), stencils.n_base, stencils.n_rows(), false, false, group_limit);
  }
  /// The `n_changed` listed vertices and `n_listed_rows` listed rows (PlanBuffers::upload_edit, buffers bound).
  void run_listed(const StencilTable& stencils, int n_changed, int n_listed_rows, int group_limit) const {
    run(stencils.first_row(), n_changed, n_listed_rows, true, true, group_limit);
  }
  /// The `n_changed` listed vertices and every stencil row: after a change of topology whose unchanged
  /// vertices' points were carried over (PlanBuffers::upload_tables).
  void run_listed_vertices(const StencilTable& stencils, int n_changed, int group_limit) const {
    run(stencils.first_row(), n_changed, stencils.n_rows(), true, false, group_limit);
  }

private:
  void run(int first_row, int vertex_count, int row_count, bool list_vertices, bool list_rows, int group_limit) const;

  ShaderProgram dual_map_[2], stencil_[2];  // by PointPrecision
  PointPrecision precision_ = PointPrecision::single_float;
};

}  // namespace gps
