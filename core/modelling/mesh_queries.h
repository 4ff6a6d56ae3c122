#pragma once
// The editor's selection tools: queries on sets of vertices (sorted ascending in and out) that walk
// the half-edge structure of the mesh, in time linear in what they visit, so that a click on a large
// mesh answers at once. They throw gps::Error naming a vertex or edge that is not in the mesh.
#include <array>
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

/// The edge loop through the edge {a, b}: from each end it continues through every interior vertex of
/// valence 4 to the edge opposite the one it arrived by (the edge sharing no face with it), until a
/// vertex of another valence, a boundary vertex, or the start again. A boundary edge gives its whole
/// boundary loop. When neither end continues (both are poles, as on a cube) the loop is the corners of
/// the face on the left of a → b. Returns the loop's vertices.
std::vector<int> edge_loop(const CovarianceMesh& mesh, int a, int b);
/// The edges of that loop, each once as (min, max), sorted: the edges walked (and the face's rim
/// where neither end continues), not every edge between its vertices.
std::vector<std::array<int, 2>> edge_loop_edges(const CovarianceMesh& mesh, int a, int b);

/// Every vertex connected to the seeds through edges.
std::vector<int> linked_vertices(const CovarianceMesh& mesh, const std::vector<int>& seeds);

/// The selection plus the vertices sharing a face with it.
std::vector<int> grow_selection(const CovarianceMesh& mesh, const std::vector<int>& vertices);
/// The selection minus its vertices that share a face with an unselected vertex.
std::vector<int> shrink_selection(const CovarianceMesh& mesh, const std::vector<int>& vertices);

/// The faces all of whose corners are selected.
std::vector<int> faces_within(const CovarianceMesh& mesh, const std::vector<int>& vertices);
/// The edges both of whose ends are selected, each once as (min, max), sorted.
std::vector<std::array<int, 2>> edges_within(const CovarianceMesh& mesh, const std::vector<int>& vertices);

/// The vertices of `edges` in order along them, where they form one simple chain: an open one from its
/// lower-numbered end, a closed one from its smallest vertex with that vertex again at the end (as
/// spin takes a profile). Throws gps::Error naming a vertex where the edges branch, or saying they
/// are not connected or there are none.
std::vector<int> chain_of_edges(const std::vector<std::array<int, 2>>& edges);

/// The vertices of a shortest path along the mesh's edges from `from` to `to` (both included; the
/// edges' lengths summed, Dijkstra's algorithm; of paths equally short, the one through lower-numbered
/// vertices), as Blender's Select Shortest Path (Ctrl+click). Throws gps::Error where no edges join them.
std::vector<int> shortest_path(const CovarianceMesh& mesh, int from, int to);
/// The faces of a shortest path across the mesh's edges from face `from` to face `to` (both included;
/// the distances between neighbouring faces' centres summed, Dijkstra's algorithm; of paths equally
/// short, the one through lower-numbered faces), as Blender's Select Shortest Path in face mode. Faces
/// flagged in `hidden` (one flag per face, where given) are not crossed. Throws gps::Error where no
/// edges join them.
std::vector<int> shortest_face_path(const CovarianceMesh& mesh, int from, int to,
                                    const std::vector<char>* hidden = nullptr);

/// The face loop across the edge {a, b}, as Blender's face loop (Alt+click in face mode): the quads on
/// either side of it, and on from each through the edge opposite the one it was entered by, until a
/// face that is not a quad, the boundary or the start again. Returns its faces, ascending.
std::vector<int> face_loop(const CovarianceMesh& mesh, int a, int b);

/// The mean of the vertices' means (zero for none): where an inset moves towards and a bevel's width
/// is measured from.
Vec3 centre_of_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices);

/// Every boundary loop of the mesh, each as its vertices in the direction of its faces' boundary
/// half-edges (a face's edge a → b on the boundary puts b after a), starting at its smallest vertex;
/// loops ordered by that vertex.
std::vector<std::vector<int>> boundary_loops(const CovarianceMesh& mesh);

}  // namespace gps
