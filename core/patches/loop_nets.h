#pragma once
// Where Loop patches find their control points in a triangle mesh (Stam 1998, "Evaluation of Loop
// subdivision surfaces"): the 12-point net of a regular triangle, with phantom points beyond a
// boundary, and the neighbourhood of a triangle at an extraordinary vertex.
#include <array>
#include <initializer_list>
#include <utility>
#include <vector>

#include "core/mesh/mesh_connectivity.h"

namespace gps {

/// A point as a combination of mesh vertices: a vertex itself, or a phantom point (three terms).
class VertexCombination {
public:
  VertexCombination() = default;
  VertexCombination(std::initializer_list<std::pair<int, double>> terms) {
    for (const auto& t : terms) terms_[size_++] = t;
  }
  const std::pair<int, double>* begin() const { return terms_.data(); }
  const std::pair<int, double>* end() const { return terms_.data() + size_; }
  size_t size() const { return size_t(size_); }
  bool empty() const { return size_ == 0; }
  const std::pair<int, double>& operator[](size_t i) const { return terms_[i]; }

private:
  std::array<std::pair<int, double>, 3> terms_{};
  int size_ = 0;
};

/// The vertex after w counter-clockwise around v in a triangle mesh (the third vertex of the face with
/// directed edge v→w), or −1 across a boundary.
int ccw_next(const PolygonTopology& t, const MeshConnectivity& c, int v, int w);
/// The vertex after w clockwise around v (the face with directed edge w→v), or −1.
int cw_next(const PolygonTopology& t, const MeshConnectivity& c, int v, int w);
/// The neighbours of v counter-clockwise, a boundary vertex's from its boundary start (TriangleWalker::fan
/// for one vertex, without the whole mesh's).
std::vector<int> triangle_fan(const PolygonTopology& t, const MeshConnectivity& c, int v);
/// Regular for Loop's box-spline patches: interior with 6 faces, or on a boundary with 3.
bool loop_regular_vertex(const MeshConnectivity& c, int v);

/// Triangle-mesh adjacency for the walks below, every vertex's fan built at once.
class TriangleWalker {
public:
  /// Builds every vertex's ring once (linear in the mesh for bounded valence).
  TriangleWalker(const PolygonTopology& topology, const MeshConnectivity& connectivity);
  int ccw_next(int v, int w) const { return gps::ccw_next(t_, c_, v, w); }
  int cw_next(int v, int w) const { return gps::cw_next(t_, c_, v, w); }
  /// The neighbours of v counter-clockwise from `first` up to a boundary, then clockwise from
  /// `first` up to the other boundary (an interior vertex: its whole ring from `first`).
  std::vector<int> ring_from(int v, int first) const;
  bool regular(int v) const { return loop_regular_vertex(c_, v); }
  const MeshConnectivity& connectivity() const { return c_; }
  /// The neighbours of v counter-clockwise, a boundary vertex's from its boundary start.
  const int* fan(int v) const { return &fans_[size_t(fan_offsets_[size_t(v)])]; }
  int fan_size(int v) const { return fan_offsets_[size_t(v) + 1] - fan_offsets_[size_t(v)]; }

private:
  const PolygonTopology& t_;
  const MeshConnectivity& c_;
  std::vector<int> fan_offsets_, fans_;
};

/// The 12 control points of the box-spline patch of the triangle (v0, v1, v2), all three regular,
/// in the order of loop_box_spline_basis() (core/patches/patch_basis.h). Beyond a boundary edge (a, b)
/// of a triangle (a, b, c) the phantom point is a + b − c: Loop's rules on the extended net then
/// give the boundary rules of core/reference/loop.h (edge midpoint, (a + 6v + b)/8).
std::array<VertexCombination, 12> loop_regular_net(const TriangleWalker& walker, int v0, int v1, int v2);
/// The same from the corners' counter-clockwise fans (a crease vertex's: its sector's, from the crease),
/// six neighbours or four where the corner is on a boundary or an infinitely sharp crease.
std::array<VertexCombination, 12> loop_regular_net(int v0, int v1, int v2, const std::array<std::vector<int>, 3>& fans);

/// The points of the triangle (v, a, b) that Loop subdivision near v reads: v, the ring of v from
/// a (TriangleWalker::ring_from), then the rings of a and b (from v) without repeats. With v
/// interior of valence N and a, b regular interior: K = N + 6 points (Stam's K).
std::vector<int> loop_extraordinary_neighbourhood(const TriangleWalker& walker, int v, int a, int b);

}  // namespace gps
