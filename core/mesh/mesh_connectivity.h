#pragma once
// Flat polygon topology and its edge/vertex adjacency, the form the subdivision loops run on.
#include <span>
#include <string>
#include <vector>

#include "core/mesh/element_names.h"

namespace gps {

/// Per-element loops over a mesh (subdivision rules, limit masks) run on all cores (OpenMP) from
/// this many elements on; below it starting the threads costs more than the loop.
constexpr int kParallelFaces = 4096;

/// Faces as vertex-index lists in compressed form (face f: verts[offsets[f] .. offsets[f+1])).
struct PolygonTopology {
  int n_vertices = 0;
  std::vector<int> offsets{0};
  std::vector<int> verts;
  int n_faces() const { return int(offsets.size()) - 1; }
  int face_size(int f) const { return offsets[size_t(f) + 1] - offsets[size_t(f)]; }
};

/// Faces given as vertex-index lists, in compressed form (n_vertices left 0 for the caller to set).
PolygonTopology polygon_topology(const std::vector<std::vector<int>>& faces);

/// Edges and incidences of a PolygonTopology. Edge e joins edge_verts[2e] < edge_verts[2e+1], the
/// edges numbered in the order of their ends (lower, then higher); edge_faces[2e+1] is −1 on a boundary
/// edge. face_edges parallels verts: the edge from corner k to k+1. Each vertex's rows list its edges
/// and faces in their order.
struct MeshConnectivity {
  std::vector<int> edge_verts;
  std::vector<int> edge_faces;
  std::vector<int> face_edges;
  std::vector<int> vertex_edge_offsets{0}, vertex_edges;  // edges around each vertex
  std::vector<int> vertex_face_offsets{0}, vertex_faces;  // faces around each vertex
  std::vector<int> vertex_face_corners;  // parallel to vertex_faces: the vertex's corner index in that face
  int n_edges() const { return int(edge_verts.size() / 2); }
  bool is_boundary_edge(int e) const { return edge_faces[2 * size_t(e) + 1] < 0; }
  int other_vertex(int e, int v) const {
    return edge_verts[2 * size_t(e)] == v ? edge_verts[2 * size_t(e) + 1] : edge_verts[2 * size_t(e)];
  }
  int valence(int v) const { return vertex_edge_offsets[size_t(v) + 1] - vertex_edge_offsets[size_t(v)]; }
  int n_vertex_faces(int v) const { return vertex_face_offsets[size_t(v) + 1] - vertex_face_offsets[size_t(v)]; }
  /// The faces around vertex v (its row), in face order.
  std::span<const int> faces_of_vertex(int v) const {
    return {vertex_faces.data() + vertex_face_offsets[size_t(v)], size_t(n_vertex_faces(v))};
  }
  /// The edge joining vertices a and b, or −1.
  int find_edge(int a, int b) const;
};

/// Builds the adjacency; the topology must be manifold (as CovarianceMesh guarantees).
MeshConnectivity connectivity_of(const PolygonTopology& topology);
/// connectivity_of in two steps: the edges, their faces and each corner's edge (the vertices' rows
/// empty), which check_manifold needs, then the rows.
MeshConnectivity edge_connectivity(const PolygonTopology& topology);
void add_vertex_rows(const PolygonTopology& topology, MeshConnectivity& c);
/// Corners as half-edges, for walks across faces: corner k stands for the half-edge from its vertex
/// to the next corner's; `twins[k]` is the corner of the other face that runs its edge the other way
/// (−1 on a boundary). Built where walks need them (4 bytes a corner each), not kept with a mesh.
struct CornerLinks {
  std::vector<int> faces, twins;  // parallel to the topology's verts
  /// The corners after and before corner k in its face (cyclically).
  int next(const PolygonTopology& t, int k) const {
    const size_t f = size_t(faces[size_t(k)]);
    return k + 1 == t.offsets[f + 1] ? t.offsets[f] : k + 1;
  }
  int previous(const PolygonTopology& t, int k) const {
    const size_t f = size_t(faces[size_t(k)]);
    return k == t.offsets[f] ? t.offsets[f + 1] - 1 : k - 1;
  }
};
CornerLinks corner_links(const PolygonTopology& topology, const MeshConnectivity& c);

/// Throws gps::Error naming `source` and the first face or vertex where `t` (whose connectivity is
/// `c`, with or without the vertices' rows) is not a manifold surface: an edge with more than two
/// faces, two faces running an edge the same way (one flipped), a vertex whose faces form more than
/// one fan, or two faces sharing all their edges.
void check_manifold(const PolygonTopology& t, const MeshConnectivity& c, const std::string& source,
                    const ElementNames& names = {});

/// The shape of a manifold mesh as a surface: its connected parts (isolated vertices are in none), its
/// boundary loops and its genus, summed over the parts, from Euler's V − E + F = 2P − 2g − b.
struct SurfaceCounts {
  int parts = 0, boundary_loops = 0, genus = 0;
};
SurfaceCounts surface_counts(const PolygonTopology& t, const MeshConnectivity& c);

/// How a vertex behaves under the boundary rules: interior, on a boundary curve, or a corner (one face).
enum class VertexRole { interior, boundary, corner, isolated };

/// The role of vertex v; for a boundary vertex, `a` and `b` get its two boundary-edge neighbours.
VertexRole vertex_role(const MeshConnectivity& c, int v, int* a = nullptr, int* b = nullptr);

}  // namespace gps
