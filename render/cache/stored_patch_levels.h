#pragma once
// The outer tessellation levels each patch of the surface cache was captured at, at adaptive levels
// (shaders/patch_level_check_comp.glsl, the tessellation control stages' rule: shaders/tess_levels.glsl).
// An edit moves plan points, and with them the adaptive levels of some patches. Where a block's
// patches all keep their levels under the capture's camera, its tessellation is the one stored,
// and its welded vertices can be evaluated again where they are (render/cache/stored_vertex_evaluation.h)
// as at uniform levels; the rest are captured again. The check reads one flag per block back.
// The plan buffers are bound (render/pipeline/plan_buffers.h), and the caller sets the programs' level
// uniforms (u_view_projection, u_viewport, u_pixels, u_level, u_debug_mismatch).
#include <vector>

#include "core/plans/patch_plans.h"
#include "render/cache/surface_blocks.h"
#include "render/gl/gl_object.h"
#include "render/gl/shape_programs.h"
#include "render/gl/point_precision.h"

namespace gps {

class StoredPatchLevels {
public:
  /// Patches [first, first + count) of the cache: a block.
  struct Block {
    int first, count;
  };
  /// Needs a current GL context.
  StoredPatchLevels();
  StoredPatchLevels(const StoredPatchLevels&) = delete;
  StoredPatchLevels& operator=(const StoredPatchLevels&) = delete;

  /// The programs for plan points of `precision` from now on (built at its first use).
  void set_precision(PointPrecision precision);
  /// The program whose level uniforms the caller sets before record() or changed().
  const ShaderProgram& program(PatchShape shape) const { return programs_(shape); }
  /// Keeps the levels of all `n_patches` (after a capture).
  void record(PatchShape shape, int n_patches, int group_limit);
  /// The levels of the patches of `moved` blocks (SurfaceCache::topology_changed) under their new
  /// numbers, with room for `n_patches`; the others' are checked and kept when their blocks are
  /// captured again. None moved (the change not followed): nothing, the next capture records all.
  void follow(int n_patches, const std::vector<SurfaceBlocks::Moved>& moved);
  /// Per block of `blocks`: whether any of its patches' levels differ from those kept; then keeps
  /// the new ones (the blocks are brought to them: evaluated again where unchanged, else captured).
  std::vector<char> changed(PatchShape shape, const std::vector<Block>& blocks, int group_limit);
  /// The kept levels' bytes.
  size_t bytes() const { return size_t(capacity_) * kBytesPerPatch; }
  static constexpr int kBytesPerPatch = 4 * 4;

private:
  void reserve(int n_patches);

  ShapePrograms programs_;
  GlBuffer levels_, patches_, changes_, spare_;
  int capacity_ = 0;  // patches the levels buffer holds
};

}  // namespace gps
