// The largest outer tessellation level among a range of patches (tess_levels.glsl, with the
// uniforms of the draw that follows): the patch draw sizes its batches by it
// (render/pipeline/patch_level_bound.h). Inner levels never exceed the outer ones.
// Preceded by `#define GPS_TRIANGLE_PATCHES` for Loop's triangle patches.
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingLevelBound) buffer LevelBound { uint max_level; };
uniform int u_first_bound_patch;

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  int p = u_first_bound_patch + i;
#ifdef GPS_TRIANGLE_PATCHES
  vec3 level = triangle_edge_levels(p);
  uint top = uint(max(level.x, max(level.y, level.z)));
#else
  vec4 level = quad_edge_levels(p);
  uint top = uint(max(max(level.x, level.y), max(level.z, level.w)));
#endif
  if (top > max_level) atomicMax(max_level, top);
}
