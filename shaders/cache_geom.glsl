// Passes the cached triangles through unchanged. On llvmpipe a vertex shader without a later
// stage projects to the viewport in its own code, which rounds differently from the projection
// after tessellation or geometry stages (~1e-6 in the interpolated AOVs); with this stage the
// cached frame equals the live one bit for bit.
#include "shaders/pass_triangle.glsl"

vec3 triangle_grid(int i) { return g_grid[i]; }
