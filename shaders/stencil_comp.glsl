// Applies the stencil table: point n_base + r = Σ w · q[index] (one sparse matrix-vector product).
layout(local_size_x = 64) in;
layout(std430, binding = 1) buffer Points { vec4 points[]; };
layout(std430, binding = 2) readonly buffer Offsets { int offsets[]; };
layout(std430, binding = 3) readonly buffer Indices { int indices[]; };
layout(std430, binding = 4) readonly buffer Weights { float weights[]; };
layout(std430, binding = 9) readonly buffer Rows { int rows[]; };
uniform int u_count;
uniform int u_n_base;
uniform int u_use_list;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= u_count) return;
  int r = u_use_list != 0 ? rows[i] : i;
  vec4 a = vec4(0.0), b = vec4(0.0), c = vec4(0.0);
  for (int k = offsets[r]; k < offsets[r + 1]; ++k) {
    int p = indices[k];
    float w = weights[k];
    a += w * points[3 * p];
    b += w * points[3 * p + 1];
    c += w * points[3 * p + 2];
  }
  int out_point = u_n_base + r;
  points[3 * out_point] = a;
  points[3 * out_point + 1] = b;
  points[3 * out_point + 2] = c;
}
