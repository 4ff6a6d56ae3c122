// The surface cache's level check (render/cache/stored_patch_levels.h): each listed patch's outer
// tessellation levels (tess_levels.glsl, under the capture's camera) against those it was captured
// at; the new ones are kept, and a block with any patch changed is flagged (its tessellation
// changed: captured again; else its welded vertices are evaluated again where they are).
// Preceded by `#define GPS_TRIANGLE_PATCHES` for Loop's triangle patches.
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingPatchLevels) buffer PatchLevels { vec4 patch_levels[]; };
layout(std430, binding = kBindingLevelPatches) readonly buffer LevelPatches { int level_patches[]; };  // patch, listed block
layout(std430, binding = kBindingLevelChanges) writeonly buffer LevelChanges { uint level_changes[]; };  // per listed block

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  int p = u_use_list != 0 ? level_patches[2 * i] : i;
#ifdef GPS_TRIANGLE_PATCHES
  vec4 level = vec4(triangle_edge_levels(p), 0.0);
#else
  vec4 level = quad_edge_levels(p);
#endif
  if (u_use_list != 0 && level != patch_levels[p]) level_changes[level_patches[2 * i + 1]] = 1u;
  patch_levels[p] = level;
}
