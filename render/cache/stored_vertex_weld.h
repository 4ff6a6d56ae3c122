#pragma once
// Welds the surface cache's stored vertices on the GPU (shaders/weld_comp.glsl): transform feedback
// stores three vertices per triangle, so a cached frame would fetch and shade every vertex about six
// times where a welded buffer shades it once. The weld gives every stored vertex the index of the
// vertex with the same position, normal and evaluated parameters (shaders/weld_comp.glsl: one
// surface point, in whichever block) that entered the hash table first; a prefix sum then numbers
// those distinct vertices block by block, and they are copied, in capture order, to a welded buffer
// that the cache draws by the renumbered indices (shaders/compact_comp.glsl). Numbered so,
// neighbouring triangles share nearby indices, as a welded static buffer's do: llvmpipe's vertex
// cache, keyed by index, then shades a shared vertex once, where numbered in capture slots a shared
// vertex would mostly miss it.
#include <memory>
#include <vector>

#include "render/cache/exclusive_scan.h"
#include "render/gl/gl_object.h"
#include "render/gl/shader_program.h"

namespace gps {

class StoredVertexWeld {
public:
  /// Needs a current GL context.
  StoredVertexWeld();
  StoredVertexWeld(const StoredVertexWeld&) = delete;
  StoredVertexWeld& operator=(const StoredVertexWeld&) = delete;

  /// A run of stored vertices: the first and how many.
  struct Range {
    long long first, count;
  };
  /// For the first `count` vertices v of `vertices` (12 words each): writes indices[v], the number
  /// of v's welded vertex, and copies the welded vertices' first 9 words to `welded_vertices` and
  /// their last 3 (the parameters evaluated) to `parameters`, each block's from the block's first
  /// vertex on (`block_starts`: each block's first vertex, ascending, the first 0), and counts each
  /// block's welded vertices (welded_counts()). Copies of a point in different blocks weld too. A
  /// barrier then makes the indices and vertices ready to draw.
  void weld(unsigned vertices, unsigned indices, unsigned welded_vertices, unsigned parameters, long long count,
            const std::vector<long long>& block_starts);
  /// After `ranges` (whole blocks) were captured again in the tessellation they had: each of their
  /// vertices keeps its index and writes its words to its welded vertex (shaders/reweld_comp.glsl).
  void weld_again(unsigned vertices, unsigned indices, unsigned welded_vertices, unsigned parameters,
                  const std::vector<Range>& ranges);
  /// Per block, how many welded vertices it has (written by a weld of the block), which an evaluation
  /// of them again runs over (render/cache/stored_vertex_evaluation.h).
  unsigned welded_counts() const { return welded_counts_; }
  /// Copies the welded vertices' position and stored normal back to every vertex v of `ranges` of
  /// `vertices`, from welded vertex indices[v] (after the welded ones were evaluated again), in one pass.
  void copy_back(unsigned vertices, unsigned indices, unsigned welded_vertices, const std::vector<Range>& ranges);
  /// The hash table's and the prefix sum's bytes (kept between welds, shrunk when four times too large).
  size_t bytes() const { return size_t(slots_) * 4 + scan_.bytes(); }
  /// Table and prefix sum bytes per welded vertex at most (its slots are twice the vertices).
  static constexpr int kTableBytesPerVertex = 8 + 5;

private:
  /// Uploads the runs of `ranges` for copy_back and weld_again (shaders/copy_runs.glsl); their vertices.
  long long upload_runs(const std::vector<Range>& ranges);

  ShaderProgram weld_, compact_, copy_back_, reweld_;
  ExclusiveScan scan_;
  GlBuffer table_, block_starts_, welded_counts_, runs_;
  long long counted_blocks_ = 0;  // blocks the welded counts buffer holds
  long long slots_ = 0;
};

}  // namespace gps
