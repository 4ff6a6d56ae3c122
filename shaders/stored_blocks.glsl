// The surface cache's blocks, as the weld passes see them (render/cache/stored_vertex_weld.h): each
// block's first stored vertex, ascending from 0.
layout(std430, binding = kBindingBlockStarts) readonly buffer BlockStarts { uint block_starts[]; };
uniform int u_blocks;

int block_of(uint v) {  // the last block starting at or before v
  int low = 0, high = u_blocks - 1;
  while (low < high) {
    int middle = (low + high + 1) / 2;
    if (block_starts[middle] <= v) low = middle;
    else high = middle - 1;
  }
  return low;
}
