// An exclusive prefix sum in place (render/cache/exclusive_scan.h), one level of it: invocation t sums
// its tile of kScanTile values serially, writing each value's exclusive sum within the tile, and
// the tile's total to the next level; with ADD_TILE_OFFSETS, each value adds its tile's scanned
// total from that next level instead.
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingScanValues) buffer ScanValues { uint values[]; };
uniform int u_level;   // this level's first value
uniform int u_length;  // its values
uniform int u_totals;  // the next level's first value: one per tile
const int kScanTile = 64;

void main() {
  int i = compute_invocation();
  if (i < 0) return;
#ifdef ADD_TILE_OFFSETS
  values[u_level + i] += values[u_totals + i / kScanTile];
#else
  int end = min((i + 1) * kScanTile, u_length);
  uint sum = 0u;
  for (int k = i * kScanTile; k < end; ++k) {
    uint value = values[u_level + k];
    values[u_level + k] = sum;
    sum += value;
  }
  values[u_totals + i] = sum;
#endif
}
