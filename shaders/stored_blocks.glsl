// The surface cache's blocks, as the weld passes see them (render/cache/stored_vertex_weld.h): each
// block's first stored vertex, ascending from 0, then per chunk of kBlockChunk stored vertices (and
// one past the last) the last block starting at or before the chunk's first vertex: a vertex searches
// only the blocks between its chunk's and the next's, most often one.
layout(std430, binding = kBindingBlockStarts) readonly buffer BlockStarts { uint block_starts[]; };
uniform int u_blocks;

int block_of(uint v) {  // the last block starting at or before v, between those of v's chunk and the next
  int chunk = u_blocks + int(v / uint(kBlockChunk));
  int low = int(block_starts[chunk]), high = int(block_starts[chunk + 1]);
  while (low < high) {
    int middle = (low + high + 1) / 2;
    if (block_starts[middle] <= v) low = middle;
    else high = middle - 1;
  }
  return low;
}
