#pragma once
// The form the modelling operations work on: a covariance mesh as plain arrays (Gaussians by vertex
// index, faces as vertex-index lists), turned back into a validated covariance mesh at the end, so
// that an operation either yields a manifold mesh or throws and changes nothing.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/mesh/dual_map.h"

namespace gps {

struct MeshArrays {
  std::vector<Vec3> means;
  std::vector<Mat3> covariances;
  std::vector<std::vector<int>> faces;
  /// Creases and corners by vertex index; build_mesh keeps the creases that are edges of the faces.
  Sharpness sharpness;
  /// Per vertex: its index in the mesh the arrays were made from (arrays_of), −1 for one added since
  /// (add_vertex); kept by drop_unused_vertices. Shorter than `means` where a vertex was added
  /// otherwise: then unknown, and the plans are built again whole (core/plans/surface_replanner.h).
  std::vector<int> origin;
  /// Per face: its index in the mesh the arrays were made from (arrays_of); faces past its end are new.
  /// Kept by the operations that remove faces, so that build_mesh can carry over the connectivity of
  /// the faces that did not change (a face counts as unchanged only where its corners are the same).
  std::vector<int> face_origin;

  MeshArrays() = default;
  MeshArrays(const MeshArrays&) = default;
  MeshArrays(MeshArrays&&) = default;
  MeshArrays& operator=(const MeshArrays&) = default;
  MeshArrays& operator=(MeshArrays&&) = default;
  /// Leaves its face lists to the next arrays_of on this thread, which fills them again: an operation
  /// would otherwise allocate and free one list per face of the mesh.
  ~MeshArrays();

  int n_vertices() const { return int(means.size()); }
  int n_faces() const { return int(faces.size()); }
  Gaussian gaussian(int v) const { return {means[size_t(v)], covariances[size_t(v)]}; }
  /// Appends a vertex; returns its index.
  int add_vertex(const Gaussian& g);
};

/// The outcome of a modelling operation: the new mesh, the vertices a user goes on working with
/// (the extruded cap, the new loop, ...; ascending) and a one-line account of what was done.
struct Modelled {
  CovarianceMesh mesh;
  std::vector<int> selection;
  std::string summary;
  /// Per vertex of `mesh`: its index before the operation, −1 for a new one (MeshArrays::origin);
  /// empty where not known.
  std::vector<int> vertex_origin;
  /// The faces an editor in face mode goes on working with (ascending), where they are not simply
  /// those whose corners are all in `selection` (a bevel's band, not the face it shrank); empty: those.
  std::vector<int> selected_faces;
};

/// The outcome of an operation from its arrays, made from `before` (arrays_of(before), then changed):
/// build_mesh's mesh, at the cost of what changed, with the vertices' origins where the arrays kept them.
/// Throws gps::Error for a result past the patch plans' limits.
Modelled modelled(const CovarianceMesh& before, const MeshArrays& arrays, std::vector<int> selection,
                  std::string summary = "");
/// The same, taking the arrays' Gaussians over instead of copying them (its means and covariances are
/// left empty).
Modelled modelled(const CovarianceMesh& before, MeshArrays&& arrays, std::vector<int> selection,
                  std::string summary = "");
/// Throws gps::Error where the faces around `result`'s new vertices (made from `before`) have no
/// surface: an edge no longer than the repair's weld tolerance (a millionth of the mesh's size) or no
/// more area than that times their longest edge, which the next repair would mend away. A parameter
/// next to nothing makes them (an extrusion by 1e-300, an inset of 0.9999999, a spin by a nanodegree).
/// Operations run from a list are held to it; the editor's tools, which make such vertices and then
/// move them (E makes its copies on the faces), are not.
void check_new_geometry(const CovarianceMesh& before, const Modelled& result);
/// Throws gps::Error as build_mesh names a Gaussian it refuses ("the result would not be a valid mesh:
/// vertex 8 has …") for the first of `vertices` (ascending) whose position or covariance has a problem:
/// an operation that checks the vertices it made or moved is refused as its build would refuse it.
void check_gaussians(const MeshArrays& arrays, const std::vector<int>& vertices);
/// The arrays' origins where they are known (one per vertex), else empty.
std::vector<int> vertex_origin(const MeshArrays& arrays);
/// The way back: for each of the `n_before` vertices of the mesh before an operation, its index after
/// it (−1 removed), from the result's `origin`; empty (indices kept) for an empty origin.
std::vector<int> inverse_origin(const std::vector<int>& origin, size_t n_before);

/// The mesh as arrays; faces in the mesh's face order, corners in the faces' order.
MeshArrays arrays_of(const CovarianceMesh& mesh);
/// An operation made on arrays (`change(arrays, summary)` changes them and returns the selection) on
/// arrays_of(before), then built: modelled()'s outcome.
template <class Change>
Modelled modelled_by(const CovarianceMesh& before, Change&& change) {
  MeshArrays a = arrays_of(before);
  std::string summary;
  std::vector<int> selection = change(a, summary);
  return modelled(before, std::move(a), std::move(selection), std::move(summary));
}

/// The arrays as a covariance mesh, with the creases of `arrays.sharpness` that are still edges of
/// the faces and the corners of its vertices. Throws gps::Error ("the result would ...: <why>") when
/// they do not make a manifold mesh of valid Gaussians.
CovarianceMesh build_mesh(const MeshArrays& arrays);
/// build_mesh for arrays made from `before` (arrays_of(before), then changed): the connectivity of the
/// faces that did not change is carried over and only new or changed Gaussians are checked
/// (make_covariance_mesh's form for a changed mesh). The same mesh, or the same error, as build_mesh.
CovarianceMesh build_mesh(const MeshArrays& arrays, const CovarianceMesh& before);

/// Drops the faces marked in `removed` (a flag per face), keeping the others in order with their origins.
void remove_faces(MeshArrays& arrays, const std::vector<char>& removed);

/// Removes the vertices no face uses, keeping the others in order (their creases and corners too);
/// returns old index → new (−1 removed).
std::vector<int> drop_unused_vertices(MeshArrays& arrays);
/// The same where `used` flags (non-zero) every vertex a face uses, found by the caller's own pass
/// over the faces.
std::vector<int> drop_unused_vertices(MeshArrays& arrays, const std::vector<char>& used);

/// Sharpness renumbered by old index → new (−1 removed) onto `n_vertices` vertices: creases with a
/// removed end, or whose ends become one vertex, are dropped; where several become one crease or
/// corner (vertices merged), the largest sharpness stays.
Sharpness renumbered(const Sharpness& sharpness, const std::vector<int>& new_index, int n_vertices);

/// Gives both halves a–m and m–b of a split edge a–b the edge's sharpness (as Blender does).
void split_crease(MeshArrays& arrays, int a, int b, int m);

/// The Gaussian whose 9D point is Σ w_k q_k over (vertex, weight) pairs (weights ≥ 0, summing to 1):
/// the normalised product of the Gaussians (docs/design.md §1), what a linear scheme gives a vertex
/// it inserts with these weights.
Gaussian blend_gaussians(const MeshArrays& arrays, const std::vector<std::pair<int, double>>& weights);

/// Whether every face is a triangle (a mesh Loop's scheme subdivides).
bool all_triangles(const MeshArrays& arrays);

/// Splits the quads from face `first` on into two triangles each, along the diagonal from their first
/// corner, so that a mesh of triangles that an operation added quads to stays one (and Loop's).
void split_new_quads(MeshArrays& arrays, int first);

/// The 9D average of a face's corners (the Catmull-Clark face point in 9D).
Gaussian face_point(const MeshArrays& arrays, int face);

/// A key for the directed edge a → b, and for the undirected edge {a, b}.
inline uint64_t directed_key(int a, int b) { return (uint64_t(uint32_t(a)) << 32) | uint32_t(b); }
inline uint64_t edge_key(int a, int b) { return a < b ? directed_key(a, b) : directed_key(b, a); }

/// Where each directed edge a → b of the faces lies: (face, corner of a in it), looked up by
/// directed_key(a, b). Either a flat open-addressing table, built over every corner of some arrays
/// (directed_edges), or a mesh's own faces looked up through its connectivity as asked, for arrays
/// that are still arrays_of(mesh): nothing built, at the cost of the edges asked about.
class DirectedEdges {
public:
  using Entry = std::pair<uint64_t, std::pair<int, int>>;
  using const_iterator = std::vector<Entry>::const_iterator;

  DirectedEdges() = default;
  /// The directed edges of `mesh`'s faces (whose shape it shares).
  explicit DirectedEdges(const CovarianceMesh& mesh) : shape_(mesh.shape()) {}

  /// Where the edge lies, or (−1, −1) where no face has it.
  std::pair<int, int> place(uint64_t key) const;
  size_t count(uint64_t key) const { return place(key).first >= 0 ? 1 : 0; }

  /// A table's own: adds the edge unless it is there already.
  void emplace(uint64_t key, std::pair<int, int> place);
  void reserve(size_t n);

private:
  const_iterator find(uint64_t key) const;
  size_t slot_of(uint64_t key) const;  // the slot holding `key`, or the empty slot where it would go
  std::vector<Entry> entries_;         // in insertion order
  std::vector<int> slots_;             // index into entries_, −1 empty; a power of two, at most half full
  std::vector<uint64_t> slot_keys_;    // per slot, its entry's key: a probe reads one array, not two
  std::shared_ptr<const MeshShape> shape_;  // the mesh looked up instead of a table, where set
};
DirectedEdges directed_edges(const MeshArrays& arrays);

/// Whether {a, b} is an edge, and whether it is a boundary edge (one face only).
bool has_edge(const DirectedEdges& edges, int a, int b);
bool is_boundary_edge(const DirectedEdges& edges, int a, int b);
/// The face holding the directed edge u → v and the corner of u in it, or (−1, −1).
std::pair<int, int> face_of_edge(const DirectedEdges& edges, int u, int v);

/// Throws a gps::Error for an index outside the mesh ("vertex 12 is not in the mesh (8 vertices)").
void check_vertex(const MeshArrays& arrays, int v);
void check_vertex(size_t n_vertices, int v);
void check_face(const MeshArrays& arrays, int f);

/// The selection of vertices for an operation: sorted, unique, each checked.
std::vector<int> sorted_vertices(const MeshArrays& arrays, std::vector<int> vertices);
std::vector<int> sorted_vertices(size_t n_vertices, std::vector<int> vertices);
std::vector<int> sorted_faces(const MeshArrays& arrays, std::vector<int> faces);

}  // namespace gps
