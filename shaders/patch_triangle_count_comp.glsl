// The surface cache's patch triangle counts (render/cache/patch_triangle_counts.h): how many triangles
// the primitive generator makes of each listed patch at the levels its control stage gives it
// (tess_levels.glsl). Under equal spacing a level is clamped to [1, max] and rounded up; an inner
// level of 1 counts as 1 + ε, so 2, unless every level is 1 (one triangle, or two for a quad). The
// triangles then tile the domain with no vertex but the boundary's B and the interior's I, so there
// are 2 I + B − 2 of them (Euler's formula for a triangulated disc). Preceded by `#define
// GPS_TRIANGLE_PATCHES` for Loop's triangle patches.
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingCountedPatches) readonly buffer CountedPatches { int counted_patches[]; };
layout(std430, binding = kBindingPatchTriangles) writeonly buffer PatchTriangles { int patch_triangles[]; };

int rounded_level(float level) { return int(ceil(clamp(level, 1.0, float(gl_MaxTessGenLevel)))); }

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  int p = counted_patches[i];
#ifdef GPS_TRIANGLE_PATCHES
  vec3 outer = triangle_edge_levels(p);
  ivec3 edges = ivec3(rounded_level(outer[0]), rounded_level(outer[1]), rounded_level(outer[2]));
  int inner = rounded_level(triangle_inner_level(outer));
  bool ones = inner == 1 && edges == ivec3(1);
  // Concentric triangles of inner - 2, inner - 4, ... segments a side, each 3 s vertices, or the
  // centre where s reaches 0.
  int interior = 0;
  for (int s = max(inner, 2) - 2; s >= 0; s -= 2) interior += s == 0 ? 1 : 3 * s;
  patch_triangles[i] = ones ? 1 : 2 * interior + edges[0] + edges[1] + edges[2] - 2;
#else
  vec4 outer = quad_edge_levels(p);
  ivec4 edges = ivec4(rounded_level(outer[0]), rounded_level(outer[1]), rounded_level(outer[2]),
                      rounded_level(outer[3]));
  vec2 inner_levels = quad_inner_levels(outer);
  ivec2 inner = ivec2(rounded_level(inner_levels[0]), rounded_level(inner_levels[1]));
  bool ones = inner == ivec2(1) && edges == ivec4(1);
  // The interior vertices: an (inner - 1)² grid.
  ivec2 grid = max(inner, ivec2(2)) - 1;
  patch_triangles[i] = ones ? 2 : 2 * grid.x * grid.y + edges[0] + edges[1] + edges[2] + edges[3] - 2;
#endif
}
