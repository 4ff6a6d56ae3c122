#include "core/reference/crease_rules.h"

#include <algorithm>
#include <limits>

namespace gps {

namespace {
// Sdc::Crease::DetermineVertexVertexRule.
VertexRule rule_of(double vertex_sharpness, int sharp_edges) {
  if (vertex_sharpness > 0.0 || sharp_edges > 2) return VertexRule::corner;
  return sharp_edges == 2 ? VertexRule::crease : sharp_edges == 1 ? VertexRule::dart : VertexRule::smooth;
}

// Records w as the next of a vertex's sharp edges' far ends (the first two are kept).
void note_sharp(int w, int& count, int& a, int& b) {
  if (count == 0) a = w;
  if (count == 1) b = w;
  ++count;
}
}  // namespace

double edge_sharpness(const MeshConnectivity& c, const CreaseLevel& level, int e) {
  if (c.is_boundary_edge(e)) return std::numeric_limits<double>::infinity();
  return size_t(e) < level.edges.size() ? level.edges[size_t(e)] : 0.0;
}

double vertex_sharpness(const MeshConnectivity& c, const CreaseLevel& level, int v) {
  if (c.n_vertex_faces(v) <= 1) return std::numeric_limits<double>::infinity();
  return size_t(v) < level.vertices.size() ? level.vertices[size_t(v)] : 0.0;
}

VertexRule vertex_rule(const MeshConnectivity& c, const CreaseLevel& level, int v, int* a, int* b) {
  int count = 0, first = -1, second = -1;
  for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i) {
    const int e = c.vertex_edges[size_t(i)];
    if (edge_sharpness(c, level, e) > 0.0) note_sharp(c.other_vertex(e, v), count, first, second);
  }
  const VertexRule rule = rule_of(vertex_sharpness(c, level, v), count);
  if (rule == VertexRule::crease) {
    if (a) *a = first;
    if (b) *b = second;
  }
  return rule;
}

VertexPointRule vertex_point_rule(const MeshConnectivity& c, const CreaseLevel& level, int v) {
  VertexPointRule r;
  const double parent_vertex = vertex_sharpness(c, level, v), child_vertex = decayed_sharpness(parent_vertex);
  int parent_count = 0, child_count = 0, transitions = 0;
  double transition_sum = 0.0;
  if (parent_vertex > 0.0 && child_vertex <= 0.0) {
    transition_sum += parent_vertex;
    ++transitions;
  }
  for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i) {
    const int e = c.vertex_edges[size_t(i)], w = c.other_vertex(e, v);
    const double parent = edge_sharpness(c, level, e), child = decayed_sharpness(parent);
    if (parent > 0.0) note_sharp(w, parent_count, r.parent_a, r.parent_b);
    if (child > 0.0) note_sharp(w, child_count, r.child_a, r.child_b);
    if (parent > 0.0 && child <= 0.0) {
      transition_sum += parent;
      ++transitions;
    }
  }
  r.parent = rule_of(parent_vertex, parent_count);
  r.child = rule_of(child_vertex, child_count);
  // Sdc blends only from a crease or corner; a dart or smooth vertex is smooth in both levels.
  const bool smooth_parent = r.parent == VertexRule::smooth || r.parent == VertexRule::dart;
  if (r.parent != r.child && !smooth_parent && transitions > 0)
    r.parent_weight = std::min(1.0, transition_sum / transitions);
  else
    r.child = r.parent;
  return r;
}

double edge_crease_weight(const MeshConnectivity& c, const CreaseLevel& level, int e) {
  return std::min(1.0, edge_sharpness(c, level, e));
}

void sharp_vertex_mask(VertexRule rule, int v, int a, int b, BoundaryRule step_or_limit, VertexMask& mask) {
  if (rule != VertexRule::crease) {
    mask.reset(1.0);
    mask.add_group(1.0, v);
    return;
  }
  const double centre = step_or_limit == BoundaryRule::step ? 6.0 : 4.0;
  mask.reset(centre + 2.0);
  mask.add_group(1.0, a);
  mask.add_group(centre, v);
  mask.add_group(1.0, b);
}

CreaseLevel refined_crease_level(const PolygonTopology& t, const MeshConnectivity& c, const CreaseLevel& parent,
                                 const MeshConnectivity& child) {
  CreaseLevel out;
  if (parent.empty()) return out;
  const int nv = t.n_vertices, ne = c.n_edges();
  out.vertices.assign(child.vertex_edge_offsets.size() - 1, 0.0);
  for (int v = 0; v < nv && size_t(v) < parent.vertices.size(); ++v)
    out.vertices[size_t(v)] = decayed_sharpness(parent.vertices[size_t(v)]);
  out.edges.assign(size_t(child.n_edges()), 0.0);
  for (int e = 0; e < child.n_edges(); ++e) {
    // A child edge from a vertex point is half of the parent edge whose point is its other end.
    const int x = child.edge_verts[2 * size_t(e)], y = child.edge_verts[2 * size_t(e) + 1];
    const int from = std::min(x, y), to = std::max(x, y);
    if (from >= nv || to < nv || to >= nv + ne) continue;
    const int parent_edge = to - nv;
    if (size_t(parent_edge) < parent.edges.size())
      out.edges[size_t(e)] = decayed_sharpness(parent.edges[size_t(parent_edge)]);
  }
  return out;
}

Sharpness sharpness_of(const MeshConnectivity& c, const CreaseLevel& level) {
  Sharpness s;
  for (int e = 0; e < c.n_edges() && size_t(e) < level.edges.size(); ++e)
    if (level.edges[size_t(e)] > 0.0)
      s.creases.push_back({c.edge_verts[2 * size_t(e)], c.edge_verts[2 * size_t(e) + 1], level.edges[size_t(e)]});
  s.corners = level.vertices;
  s.normalise();
  return s;
}

}  // namespace gps
