#include "core/reference/vertex_mask.h"

namespace gps {

void VertexMask::reset(double denominator) {
  points_.clear();
  group_begins_.clear();
  group_weights_.clear();
  denominator_ = denominator;
}

void VertexMask::begin_group(double weight) {
  group_begins_.push_back(int(points_.size()));
  group_weights_.push_back(weight);
}

std::vector<std::pair<int, double>> VertexMask::terms() const {
  std::vector<std::pair<int, double>> out;
  out.reserve(points_.size());
  for (size_t g = 0; g < group_weights_.size(); ++g)
    for (int i = group_begins_[g]; i < group_end(g); ++i)
      out.emplace_back(points_[size_t(i)], group_weights_[g] / denominator_);
  return out;
}

bool boundary_mask(const MeshConnectivity& c, int v, BoundaryRule rule, VertexMask& mask) {
  int a = -1, b = -1;
  switch (vertex_role(c, v, &a, &b)) {
    case VertexRole::isolated:
    case VertexRole::corner:
      mask.reset(1.0);
      mask.add_group(1.0, v);
      return true;
    case VertexRole::boundary: {
      const double centre = rule == BoundaryRule::step ? 6.0 : 4.0;
      mask.reset(centre + 2.0);
      mask.add_group(1.0, a);
      mask.add_group(centre, v);
      mask.add_group(1.0, b);
      return true;
    }
    case VertexRole::interior:
      return false;
  }
  return false;
}

namespace {
// One group: the edge neighbours of v, in vertex_edges order.
void add_edge_neighbours(const MeshConnectivity& c, int v, double weight, VertexMask& mask) {
  mask.begin_group(weight);
  for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i)
    mask.add(c.other_vertex(c.vertex_edges[size_t(i)], v));
}
}  // namespace

void catmull_clark_limit_mask(const PolygonTopology& t, const MeshConnectivity& c, int v, VertexMask& mask) {
  if (!boundary_mask(c, v, BoundaryRule::limit, mask)) catmull_clark_smooth_limit_mask(t, c, v, mask);
}

void catmull_clark_smooth_limit_mask(const PolygonTopology& t, const MeshConnectivity& c, int v, VertexMask& mask) {
  const double n = c.valence(v);
  mask.reset(n * (n + 5.0));
  mask.add_group(n * n, v);
  add_edge_neighbours(c, v, 4.0, mask);
  mask.begin_group(1.0);  // the diagonals: the corner across each face from v
  for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i) {
    const int f = c.vertex_faces[size_t(i)], k = c.vertex_face_corners[size_t(i)];
    mask.add(t.verts[size_t(t.offsets[size_t(f)] + (k + 2) % t.face_size(f))]);
  }
}

void loop_vertex_mask(const MeshConnectivity& c, int v, LoopBeta kind, VertexMask& mask) {
  if (!boundary_mask(c, v, BoundaryRule::step, mask)) loop_smooth_vertex_mask(c, v, kind, mask);
}

void loop_smooth_vertex_mask(const MeshConnectivity& c, int v, LoopBeta kind, VertexMask& mask) {
  const int n = c.valence(v);
  const double beta = loop_beta(n, kind);
  mask.reset(1.0);
  mask.add_group(1.0 - n * beta, v);
  add_edge_neighbours(c, v, beta, mask);
}

void loop_limit_mask(const MeshConnectivity& c, int v, LoopBeta kind, VertexMask& mask) {
  if (!boundary_mask(c, v, BoundaryRule::limit, mask)) loop_smooth_limit_mask(c, v, kind, mask);
}

void loop_smooth_limit_mask(const MeshConnectivity& c, int v, LoopBeta kind, VertexMask& mask) {
  const int n = c.valence(v);
  const double chi = 1.0 / (3.0 / (8.0 * loop_beta(n, kind)) + n);
  mask.reset(1.0);
  mask.add_group(1.0 - n * chi, v);
  add_edge_neighbours(c, v, chi, mask);
}

}  // namespace gps
