// Runs of the surface cache's stored vertices that one pass runs over (render/cache/stored_vertex_weld.h):
// invocation i stands for vertex i − (its run's invocations before) past its run's first.
layout(std430, binding = kBindingCopyRuns) readonly buffer CopyRuns { uint runs[]; };  // per run: first vertex, invocations before
uniform int u_runs;

uint run_vertex(int i) {
  int low = 0, high = u_runs - 1;  // the last run whose invocations start at or before i
  while (low < high) {
    int middle = (low + high + 1) / 2;
    if (runs[2 * middle + 1] <= uint(i)) low = middle;
    else high = middle - 1;
  }
  return runs[2 * low] + uint(i) - runs[2 * low + 1];
}
