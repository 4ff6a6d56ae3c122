// Renumbers the patches the surface cache's captured vertices name (the patch each was evaluated at,
// as shaders/limit_point_tese.glsl stores it: the patch, or −(patch + 1) for a crease's edge point,
// limit_point.glsl) after a change of topology that kept their patches under other numbers
// (render/cache/stored_patch_renumbering.h). One invocation per captured vertex.
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingStoredVertices) buffer StoredVertices { float stored[]; };  // 12 floats a vertex
layout(std430, binding = kBindingPatchNumbers) readonly buffer PatchNumbers { int new_number[]; };

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  uint at = 12u * uint(i) + 9u;
  float patch_id = stored[at];
  stored[at] = patch_id >= 0.0 ? float(new_number[int(patch_id)]) : -float(new_number[-int(patch_id) - 1] + 1);
}
