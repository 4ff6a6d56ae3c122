// Counts the pixels of a frame whose position or normal (attachments 1 and 2 of
// render/gl/render_target.h) is not finite, so that one number is read back, not both float images.
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0, rgba32f) readonly uniform image2D u_position;
layout(binding = 1, rgba32f) readonly uniform image2D u_normal;
layout(binding = 0, offset = 0) uniform atomic_uint u_non_finite;

bool finite(vec4 v) { return !any(isnan(v)) && !any(isinf(v)); }

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(u_position)))) return;
  if (!finite(imageLoad(u_position, pixel)) || !finite(imageLoad(u_normal, pixel))) atomicCounterIncrement(u_non_finite);
}
