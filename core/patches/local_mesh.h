#pragma once
// A piece of a subdivided mesh around one face, its vertices as stencils over the base vertices
// of the neighbourhood, kept dense (docs/design.md §2 step 2). A vertex is "complete" when every face it has in the
// whole mesh at that level is present, so that its Catmull-Clark vertex point (and the edge points of its edges) can
// be computed from the piece alone.
#include <memory>
#include <vector>

#include "core/mesh/mesh_connectivity.h"
#include "core/mesh/mesh_shape.h"
#include "core/mesh/sharpness.h"
#include <Eigen/Core>

#include "core/patches/stencil.h"
#include "core/reference/loop.h"

namespace gps {

struct LocalMesh {
  /// The faces and their connectivity: a base mesh's are its covariance mesh's, shared.
  std::shared_ptr<const MeshShape> shape = empty_mesh_shape();
  std::vector<int> base_ids;            // the base vertices the stencils combine (empty when `is_base`)
  std::vector<Eigen::VectorXd> points;  // per vertex: weights over base_ids; empty when `is_base`
  std::vector<char> complete;
  CreaseLevel creases;  // per edge and vertex; both empty where the mesh has no sharpness
  bool is_base = false;  // the whole base mesh: vertex i is base vertex i

  const PolygonTopology& topology() const { return shape->topology; }
  const MeshConnectivity& connectivity() const { return shape->connectivity; }
  /// Makes `faces` (with its n_vertices set) the piece's faces, with their connectivity.
  void set_faces(PolygonTopology&& faces);

  /// The stencil of vertex v over the global base vertices.
  Stencil point(int v) const;
  /// The stencil of Σ w·vertex over the global base vertices.
  Stencil combination(const std::vector<std::pair<int, double>>& terms) const;
  /// The face with exactly these corners (in any rotation), or −1.
  int find_face(const std::vector<int>& corners) const;
  /// The edge joining a and b, or −1.
  int find_edge(int a, int b) const;
  bool has_creases() const { return !creases.edges.empty(); }
  double edge_sharpness(int e) const { return has_creases() ? creases.edges[size_t(e)] : 0.0; }
  double vertex_sharpness(int v) const { return has_creases() ? creases.vertices[size_t(v)] : 0.0; }
  /// Whether edge e acts as a boundary of the surface on each side: a boundary edge or an infinitely
  /// sharp crease, across which the limit surface of either side reads nothing of the other.
  bool is_cut_edge(int e) const { return connectivity().is_boundary_edge(e) || is_infinitely_sharp(edge_sharpness(e)); }
  /// What the sharp rules see at vertex v: a semi-sharp edge or corner (sharpness that decays), the
  /// number of cut edges, and whether v is an infinitely sharp corner.
  struct VertexSharpness {
    bool semi_sharp = false;
    int cut_edges = 0;
    bool sharp_corner = false;
  };
  VertexSharpness sharpness_at(int v) const;
};

/// The whole base mesh as a LocalMesh (every vertex complete, identity stencils), with the mesh's
/// sharpness laid out on it (none when `sharpness` is empty).
LocalMesh base_local_mesh(const PolygonTopology& topology, const Sharpness& sharpness = {});
/// The same with the topology's connectivity already built (a covariance mesh's own).
LocalMesh base_local_mesh(const PolygonTopology& topology, const MeshConnectivity& connectivity,
                          const Sharpness& sharpness = {});
/// The same over a covariance mesh's shape, shared rather than copied.
LocalMesh base_local_mesh(std::shared_ptr<const MeshShape> shape, const Sharpness& sharpness = {});

/// The faces around the given vertices (their 1-ring), renumbered, with completeness carried over.
LocalMesh extract_neighbourhood(const LocalMesh& m, const std::vector<int>& corners, std::vector<int>& new_index);

/// One Catmull-Clark step of the piece, by OpenSubdiv's crease rules where it has sharpness. Vertex points of complete vertices, edge points of edges
/// with all their faces present, and face points are exact; the others are marked incomplete and
/// must not be read (plan_builder asserts it).
LocalMesh refine_local_mesh(const LocalMesh& m);

/// The same with one Loop step (a piece of a triangle mesh).
LocalMesh refine_local_mesh_loop(const LocalMesh& m, LoopBeta beta);

}  // namespace gps
