#pragma once
// Welds the surface cache's stored vertices on the GPU (shaders/weld_comp.glsl): transform feedback
// stores three vertices per triangle, so a cached frame would fetch and shade every vertex about six
// times where a welded buffer shades it once (on an NVIDIA H200, 1.2 M cached vertices drew in 2 x
// the welded floor's time). The weld gives every stored vertex the index of the vertex of its
// block with the same 36 bytes that entered the hash table first, and the cache draws those indices.
#include <vector>

#include "render/shader_program.h"

namespace gps {

class StoredVertexWeld {
public:
  /// Needs a current GL context.
  StoredVertexWeld();
  ~StoredVertexWeld();
  StoredVertexWeld(const StoredVertexWeld&) = delete;
  StoredVertexWeld& operator=(const StoredVertexWeld&) = delete;

  /// A run of stored vertices: the first and how many.
  struct Range {
    long long first, count;
  };
  /// Writes indices[v] for the vertices v of each range of `vertices` (9 words each), welding only
  /// within the blocks that `block_starts` (each block's first vertex, ascending, the first 0)
  /// delimit; a barrier then makes the indices ready to draw.
  void weld(unsigned vertices, unsigned indices, const std::vector<Range>& ranges, const std::vector<long long>& block_starts);
  /// The hash table's bytes (kept between welds, shrunk when four times too large).
  size_t bytes() const { return size_t(slots_) * 4; }
  /// Table bytes per welded vertex at most (its slots are twice the vertices).
  static constexpr int kTableBytesPerVertex = 8;

private:
  ShaderProgram program_;
  unsigned table_ = 0, block_starts_ = 0;
  long long slots_ = 0;
};

}  // namespace gps
