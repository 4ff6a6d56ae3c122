#pragma once
// How many triangles the tessellation makes of each patch, found from the levels its control stage
// gives it (shaders/patch_triangle_count_comp.glsl) rather than counted: the surface cache captures a
// block of patches under one query, and locates a patch's triangles inside a block by these counts
// where a change of topology leaves some of the block's patches as they were (render/cache/surface_cache.h).
// The plan buffers are bound (render/pipeline/plan_buffers.h), and the caller sets the program's level
// uniforms (u_view_projection, u_viewport, u_pixels, u_level, u_debug_mismatch).
#include <vector>

#include "core/plans/patch_plans.h"
#include "render/gl/gl_object.h"
#include "render/gl/point_precision.h"
#include "render/gl/shape_programs.h"

namespace gps {

class PatchTriangleCounts {
public:
  /// Needs a current GL context.
  PatchTriangleCounts();
  PatchTriangleCounts(const PatchTriangleCounts&) = delete;
  PatchTriangleCounts& operator=(const PatchTriangleCounts&) = delete;

  /// The programs for plan points of `precision` from now on (built at its first use).
  void set_precision(PointPrecision precision);
  /// The program whose level uniforms the caller sets before count().
  const ShaderProgram& program(PatchShape shape) const { return programs_(shape); }
  /// The triangle counts of `patches`, in their order.
  std::vector<int> count(PatchShape shape, const std::vector<int>& patches, int group_limit);

private:
  ShapePrograms programs_;
  GlBuffer patches_, counts_;
};

}  // namespace gps
