#include "core/patches/triangle_sectors.h"

#include "core/patches/quad_nets.h"

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
  const auto [semi_sharp, cut, sharp_corner] = m.sharpness_at(v);
  if (semi_sharp) return false;
  // Sdc's rules: a sharp vertex, more than two sharp edges, or a boundary vertex with one face is a
  // corner, which no box spline follows; one sharp edge is a dart.
  if (sharp_corner || cut == 1 || cut > 2 || m.connectivity().n_vertex_faces(v) == 1) return false;
  const int faces = int(sector_fan(m, v, q).size()) - (cut == 2 ? 1 : 0);
  return cut == 0 ? faces == 6 : faces == 3;
}

}  // namespace gps
