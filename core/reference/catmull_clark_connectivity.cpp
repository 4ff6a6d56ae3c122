#include "core/reference/catmull_clark_connectivity.h"

#include <algorithm>

#include "core/reference/refined_outer_edges.h"

namespace gps {

MeshConnectivity catmull_clark_connectivity(const PolygonTopology& t, const MeshConnectivity& c) {
  const int nv = t.n_vertices, ne = c.n_edges(), nf = t.n_faces(), n_corners = int(t.verts.size());
  const int edge_base = nv, face_base = nv + ne;  // catmull_clark_topology's numbering
  const bool parallel = nf >= kParallelFaces;
  // Coarse corner i is refined face i, (v_k, e'_k, f', e'_{k-1}). Side j of edge e is its face
  // edge_faces[2e + j]: there, the corner whose edge to the next corner is e, and that next corner.
  std::vector<int> side_corner(2 * size_t(ne)), side_next(2 * size_t(ne));
#pragma omp parallel for if (parallel)
  for (int f = 0; f < nf; ++f) {
    const int o = t.offsets[size_t(f)], n = t.face_size(f);
    for (int k = 0; k < n; ++k) {
      const int e = c.face_edges[size_t(o + k)], j = c.edge_faces[2 * size_t(e)] == f ? 0 : 1;
      side_corner[2 * size_t(e) + size_t(j)] = o + k;
      side_next[2 * size_t(e) + size_t(j)] = o + (k + 1) % n;
    }
  }
  // Refined edges sorted by lower then higher vertex, as connectivity_of numbers them: first the
  // outer halves (v, e') of each vertex v's edges e, at v's vertex_edges indices; then the inner
  // edges (e', f') of each edge e and side j, at inner_begin[e] + j.
  const std::vector<int> outer = outer_half_edges(c, nv, parallel);
  std::vector<int> inner_begin(size_t(ne) + 1);
  inner_begin[0] = 2 * ne;
  for (int e = 0; e < ne; ++e) inner_begin[size_t(e) + 1] = inner_begin[size_t(e)] + (c.is_boundary_edge(e) ? 1 : 2);
  const auto outer_at = [&](int e, int v) { return outer[2 * size_t(e) + (c.edge_verts[2 * size_t(e)] == v ? 0 : 1)]; };
  const auto inner_at = [&](int e, int f) {
    return inner_begin[size_t(e)] + (c.edge_faces[2 * size_t(e)] == f ? 0 : 1);
  };

  MeshConnectivity r;
  const size_t n_edges = size_t(inner_begin[size_t(ne)]);
  r.edge_verts.resize(2 * n_edges);
  r.edge_faces.resize(2 * n_edges);
  r.face_edges.resize(4 * size_t(n_corners));
  const size_t n_vertices = size_t(face_base + nf);
  r.vertex_edge_offsets.resize(n_vertices + 1);
  r.vertex_edges.resize(2 * n_edges);
  r.vertex_face_offsets.resize(n_vertices + 1);
  r.vertex_faces.resize(4 * size_t(n_corners));
  r.vertex_face_corners.resize(4 * size_t(n_corners));
#pragma omp parallel if (parallel)
  {
    // Vertex points: their outer halves, one refined face (corner 0) per coarse face around them.
#pragma omp for nowait
    for (int v = 0; v < nv; ++v) {
      write_outer_half_edges(c, v, nv, r);
      for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i) {
        const int e = c.vertex_edges[size_t(i)];
        for (int j = 0; j < 2; ++j) {
          const int corner = side_corner[2 * size_t(e) + size_t(j)];
          r.edge_faces[2 * size_t(i) + size_t(j)] = j == 1 && c.is_boundary_edge(e) ? -1
                                                    : t.verts[size_t(corner)] == v
                                                        ? corner
                                                        : side_next[2 * size_t(e) + size_t(j)];
        }
      }
      r.vertex_face_offsets[size_t(v)] = c.vertex_face_offsets[size_t(v)];
      for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i) {
        r.vertex_faces[size_t(i)] = t.offsets[size_t(c.vertex_faces[size_t(i)])] + c.vertex_face_corners[size_t(i)];
        r.vertex_face_corners[size_t(i)] = 0;
      }
    }
    // Edge points: two outer halves and the inner edges; per side, the refined faces at the edge's
    // corner (the edge point is its corner 1) and at the next (corner 3), in face order.
#pragma omp for nowait
    for (int e = 0; e < ne; ++e) {
      const int sides = inner_begin[size_t(e) + 1] - inner_begin[size_t(e)];
      const int edge_offset = 2 * e + inner_begin[size_t(e)];
      r.vertex_edge_offsets[size_t(edge_base + e)] = edge_offset;
      r.vertex_edges[size_t(edge_offset)] = outer[2 * size_t(e)];
      r.vertex_edges[size_t(edge_offset) + 1] = outer[2 * size_t(e) + 1];
      const int face_offset = n_corners + 2 * (inner_begin[size_t(e)] - 2 * ne);
      r.vertex_face_offsets[size_t(edge_base + e)] = face_offset;
      for (int j = 0; j < sides; ++j) {
        const size_t id = size_t(inner_begin[size_t(e)] + j);
        const int a = side_corner[2 * size_t(e) + size_t(j)], b = side_next[2 * size_t(e) + size_t(j)];
        r.edge_verts[2 * id] = edge_base + e;
        r.edge_verts[2 * id + 1] = face_base + c.edge_faces[2 * size_t(e) + size_t(j)];
        r.edge_faces[2 * id] = std::min(a, b);
        r.edge_faces[2 * id + 1] = std::max(a, b);
        r.vertex_edges[size_t(edge_offset + 2 + j)] = int(id);
        const size_t at = size_t(face_offset + 2 * j);
        r.vertex_faces[at] = std::min(a, b);
        r.vertex_face_corners[at] = a < b ? 1 : 3;
        r.vertex_faces[at + 1] = std::max(a, b);
        r.vertex_face_corners[at + 1] = a < b ? 3 : 1;
      }
    }
    // Refined faces, and face points: their inner edges in edge order, corner 2 of each child.
#pragma omp for
    for (int f = 0; f < nf; ++f) {
      const int o = t.offsets[size_t(f)], n = t.face_size(f);
      const size_t edge_offset = size_t(4 * ne + n_corners + o), face_offset = size_t(3 * n_corners + o);
      r.vertex_edge_offsets[size_t(face_base + f)] = int(edge_offset);
      r.vertex_face_offsets[size_t(face_base + f)] = int(face_offset);
      for (int k = 0; k < n; ++k) {
        const int v = t.verts[size_t(o + k)];
        const int e = c.face_edges[size_t(o + k)], d = c.face_edges[size_t(o + (k + n - 1) % n)];
        int* edges = &r.face_edges[4 * size_t(o + k)];
        edges[0] = outer_at(e, v);
        edges[1] = inner_at(e, f);
        edges[2] = inner_at(d, f);
        edges[3] = outer_at(d, v);
        r.vertex_edges[edge_offset + size_t(k)] = edges[1];
        r.vertex_faces[face_offset + size_t(k)] = o + k;
        r.vertex_face_corners[face_offset + size_t(k)] = 2;
      }
      std::sort(r.vertex_edges.begin() + std::ptrdiff_t(edge_offset),
                r.vertex_edges.begin() + std::ptrdiff_t(edge_offset) + n);
    }
  }
  r.vertex_edge_offsets[n_vertices] = int(2 * n_edges);
  r.vertex_face_offsets[n_vertices] = 4 * n_corners;
  return r;
}

}  // namespace gps
