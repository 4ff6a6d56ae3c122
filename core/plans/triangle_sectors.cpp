#include "core/plans/triangle_sectors.h"

#include "core/plans/quad_nets.h"

namespace gps {

std::vector<int> sector_fan(const LocalMesh& m, int v, int q) {
  // Clockwise to the cut edge that opens the sector, if any: across v→f[k+1].
  int start = q;
  for (int f = q;;) {
    const int e = m.find_edge(v, face_vertex(m, f, corner_index(m, f, v) + 1));
    if (m.is_cut_edge(e)) break;
    f = other_face(m, e, f);
    if (f == q) break;  // all the way round: the ring closes
    start = f;
  }
  std::vector<int> fan = {face_vertex(m, start, corner_index(m, start, v) + 1)};
  for (int f = start;;) {  // counter-clockwise: each triangle adds its third corner, then across x→v
    const int x = face_vertex(m, f, corner_index(m, f, v) + 2);
    const int e = m.find_edge(v, x);
    if (!m.is_cut_edge(e) && other_face(m, e, f) == start) break;  // x is the ring's first neighbour
    fan.push_back(x);
    if (m.is_cut_edge(e)) break;
    f = other_face(m, e, f);
  }
  return fan;
}

bool regular_loop_corner(const LocalMesh& m, int v, int q) {
  if (!m.complete[size_t(v)]) return false;
  const double corner = m.vertex_sharpness(v);
  if (corner > 0.0 && !is_infinitely_sharp(corner)) return false;
  const auto& c = m.connectivity;
  int cut = 0;
  for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i) {
    const int e = c.vertex_edges[size_t(i)];
    const double s = m.edge_sharpness(e);
    if (s > 0.0 && !is_infinitely_sharp(s)) return false;
    cut += m.is_cut_edge(e) ? 1 : 0;
  }
  // Sdc's rules: a sharp vertex, more than two sharp edges, or a boundary vertex with one face is a
  // corner, which no box spline follows; one sharp edge is a dart.
  if (corner > 0.0 || cut == 1 || cut > 2 || c.n_vertex_faces(v) == 1) return false;
  const int faces = int(sector_fan(m, v, q).size()) - (cut == 2 ? 1 : 0);
  return cut == 0 ? faces == 6 : faces == 3;
}

}  // namespace gps
