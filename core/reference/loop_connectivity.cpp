#include "core/reference/loop_connectivity.h"

#include <algorithm>

#include "core/reference/refined_outer_edges.h"

namespace gps {

MeshConnectivity loop_connectivity(const PolygonTopology& t, const MeshConnectivity& c) {
  const int nv = t.n_vertices, ne = c.n_edges(), nf = t.n_faces();
  const bool parallel = nf >= kParallelFaces;
  // loop_topology's numbering: vertex v, edge point nv + e; coarse face f (edges e_k = face_edges of
  // corner k) gives the children 4f + k = (v_k, e_k, e_{k−1}) and 4f + 3 = (e_0, e_1, e_2).
  const auto face_edge = [&](int f, int k) { return c.face_edges[size_t(3 * f + (k + 3) % 3)]; };
  // Refined edges sorted by lower then higher vertex, as connectivity_of numbers them: first the
  // outer halves (v, e') of each vertex v's edges, at v's vertex_edges indices; then the inner edges
  // (e'_a, e'_b) of each face, grouped by their lower edge point e'_a, at inner_begin[a] on.
  const std::vector<int> outer = outer_half_edges(c, nv, parallel);
  const auto outer_at = [&](int e, int v) { return outer[2 * size_t(e) + (c.edge_verts[2 * size_t(e)] == v ? 0 : 1)]; };
  // Inner edges by lower edge: each face's pair (e_k, e_{k−1}) counts for the lower of the two.
  std::vector<int> inner_begin(size_t(ne) + 1, 0);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) ++inner_begin[size_t(std::min(face_edge(f, k), face_edge(f, k - 1))) + 1];
  inner_begin[0] = 2 * ne;
  for (int e = 0; e < ne; ++e) inner_begin[size_t(e) + 1] += inner_begin[size_t(e)];
  // Within a group, by the higher edge point, then by face (as connectivity_of pairs the half-edges
  // of a pair that two faces share, of a mesh of two triangles on the same three vertices): at most
  // four (two faces, two pairs each). inner_id[3f + k]: the id of face f's (e_k, e_{k−1}).
  std::vector<std::pair<int, int>> inner(3 * size_t(nf));  // (higher edge, 3f + k) at id − 2ne
  {
    std::vector<int> next(inner_begin.begin(), inner_begin.end() - 1);
    for (int f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = face_edge(f, k), b = face_edge(f, k - 1);
        inner[size_t(next[size_t(std::min(a, b))]++ - 2 * ne)] = {std::max(a, b), 3 * f + k};
      }
  }
  std::vector<int> inner_id(3 * size_t(nf));
#pragma omp parallel for if (parallel)
  for (int e = 0; e < ne; ++e) {
    const auto first = inner.begin() + (inner_begin[size_t(e)] - 2 * ne),
               last = inner.begin() + (inner_begin[size_t(e) + 1] - 2 * ne);
    std::sort(first, last);
    for (auto it = first; it != last; ++it) inner_id[size_t(it->second)] = 2 * ne + int(it - inner.begin());
  }

  MeshConnectivity r;
  const size_t n_edges = size_t(2 * ne + 3 * nf), n_vertices = size_t(nv + ne), n_corners = 12 * size_t(nf);
  r.edge_verts.resize(2 * n_edges);
  r.edge_faces.resize(2 * n_edges);
  r.face_edges.resize(n_corners);
  r.vertex_edge_offsets.resize(n_vertices + 1);
  r.vertex_edges.resize(2 * n_edges);
  r.vertex_face_offsets.resize(n_vertices + 1);
  r.vertex_faces.resize(n_corners);
  r.vertex_face_corners.resize(n_corners);
  // Edge points' rows after the vertices': two outer halves and two inner edges per face of the
  // edge; three children per face of the edge.
  std::vector<int> edge_row(size_t(ne) + 1), face_row(size_t(ne) + 1);
  edge_row[0] = 2 * ne;
  face_row[0] = 3 * nf;  // a coarse vertex is in one child per coarse face at it: 3 nf in all
  for (int e = 0; e < ne; ++e) {
    const int faces = c.is_boundary_edge(e) ? 1 : 2;
    edge_row[size_t(e) + 1] = edge_row[size_t(e)] + 2 + 2 * faces;
    face_row[size_t(e) + 1] = face_row[size_t(e)] + 3 * faces;
  }
#pragma omp parallel if (parallel)
  {
    // Vertices: their outer halves, and the child at their corner of each coarse face around them.
#pragma omp for nowait
    for (int v = 0; v < nv; ++v) {
      write_outer_half_edges(c, v, nv, r);
      for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i) {
        const int e = c.vertex_edges[size_t(i)];
        for (int j = 0; j < 2; ++j) {
          const int f = c.edge_faces[2 * size_t(e) + size_t(j)];
          int k = 0;
          if (f >= 0)
            while (t.verts[size_t(3 * f + k)] != v) ++k;
          r.edge_faces[2 * size_t(i) + size_t(j)] = f < 0 ? -1 : 4 * f + k;
        }
      }
      r.vertex_face_offsets[size_t(v)] = c.vertex_face_offsets[size_t(v)];
      for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i) {
        r.vertex_faces[size_t(i)] = 4 * c.vertex_faces[size_t(i)] + c.vertex_face_corners[size_t(i)];
        r.vertex_face_corners[size_t(i)] = 0;
      }
    }
    // Edge points: two outer halves, then the inner edges; per face of the edge (edge k of it), the
    // children 4f + k (corner 1), 4f + k + 1 (corner 2) and 4f + 3 (corner k), in child order.
#pragma omp for nowait
    for (int e = 0; e < ne; ++e) {
      int* edges = &r.vertex_edges[size_t(edge_row[size_t(e)])];
      r.vertex_edge_offsets[size_t(nv + e)] = edge_row[size_t(e)];
      edges[0] = outer[2 * size_t(e)];
      edges[1] = outer[2 * size_t(e) + 1];
      int n_edges_here = 2;
      r.vertex_face_offsets[size_t(nv + e)] = face_row[size_t(e)];
      int at = face_row[size_t(e)];
      for (int j = 0; j < 2; ++j) {
        const int f = c.edge_faces[2 * size_t(e) + size_t(j)];
        if (f < 0) continue;
        int k = 0;
        while (face_edge(f, k) != e) ++k;
        edges[n_edges_here++] = inner_id[3 * size_t(f) + size_t(k)];            // (e_k, e_{k−1})
        edges[n_edges_here++] = inner_id[3 * size_t(f) + size_t((k + 1) % 3)];  // (e_{k+1}, e_k)
        const int first = 4 * f + k, second = 4 * f + (k + 1) % 3;
        const int faces[3][2] = {{std::min(first, second), first < second ? 1 : 2},
                                 {std::max(first, second), first < second ? 2 : 1},
                                 {4 * f + 3, k}};
        for (const auto& [face, corner] : faces) {
          r.vertex_faces[size_t(at)] = face;
          r.vertex_face_corners[size_t(at)] = corner;
          ++at;
        }
      }
      std::sort(edges + 2, edges + n_edges_here);
    }
    // Inner edges: their ends and faces (the corner child, then the middle one).
#pragma omp for nowait
    for (int f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) {
        const size_t id = size_t(inner_id[3 * size_t(f) + size_t(k)]);
        const int a = face_edge(f, k), b = face_edge(f, k - 1);
        r.edge_verts[2 * id] = nv + std::min(a, b);
        r.edge_verts[2 * id + 1] = nv + std::max(a, b);
        r.edge_faces[2 * id] = 4 * f + k;
        r.edge_faces[2 * id + 1] = 4 * f + 3;
      }
      // Children's edges, corner k to k + 1.
#pragma omp for
    for (int f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) {
        const int v = t.verts[size_t(3 * f + k)], e = face_edge(f, k), d = face_edge(f, k - 1);
        int* child = &r.face_edges[12 * size_t(f) + 3 * size_t(k)];  // (v_k, e_k, e_{k−1})
        child[0] = outer_at(e, v);
        child[1] = inner_id[3 * size_t(f) + size_t(k)];
        child[2] = outer_at(d, v);
        r.face_edges[12 * size_t(f) + 9 + size_t(k)] = inner_id[3 * size_t(f) + size_t((k + 1) % 3)];  // (e_k, e_{k+1})
      }
  }
  r.vertex_edge_offsets[n_vertices] = int(2 * n_edges);
  r.vertex_face_offsets[n_vertices] = int(n_corners);
  return r;
}

}  // namespace gps
