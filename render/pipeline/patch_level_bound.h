#pragma once
// The largest tessellation level a range of patches gets in the next draw, from a compute pass over
// their edges with the draw program's own level uniforms (shaders/patch_level_bound_comp.glsl). The
// patch draw sizes its batches by it: under adaptive levels most frames of a large mesh tessellate
// far below the worst case, and a batch sized for the worst case holds a handful of patches.
#include "core/plans/plan_builder.h"
#include "render/gl/gl_object.h"
#include "render/gl/point_precision.h"
#include "render/gl/shader_program.h"
#include "render/gl/shape_programs.h"

namespace gps {

class PatchLevelBound {
public:
  /// Needs a current GL 4.5 context.
  PatchLevelBound();
  PatchLevelBound(const PatchLevelBound&) = delete;
  PatchLevelBound& operator=(const PatchLevelBound&) = delete;

  /// The programs for points of `precision` from now on (built at its first use).
  void set_precision(PointPrecision precision);
  /// The largest outer level (1..64) of patches [first_patch, first_patch + n_patches) under the level
  /// uniforms `draw_program` holds (tess_levels.glsl's: camera, viewport, pixels, level), with the
  /// plan buffers bound. Leaves `draw_program` current.
  int max_level(PatchShape shape, const ShaderProgram& draw_program, int first_patch, int n_patches) const;

private:
  // By PointPrecision: quad and triangle patches.
  ShapePrograms programs_;
  GlBuffer result_;
};

}  // namespace gps
