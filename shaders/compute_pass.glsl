// What the listed compute passes share (render/gl/compute_limits.h, run_compute_pass): their work
// groups, and the items they run over: item i of u_count is i itself, or with u_use_list the
// list's i-th entry. main() starts with compute_invocation(), which is −1 past the end.
layout(local_size_x = kWorkGroupSize) in;
uniform int u_count;
uniform int u_first;  // this dispatch's first invocation (dispatches split to the device's group limit)
uniform int u_use_list;

int compute_invocation() {
  int i = u_first + int(gl_GlobalInvocationID.x);
  return i < u_count ? i : -1;
}
