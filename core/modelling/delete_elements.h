#pragma once
// Deleting and dissolving vertices, edges and faces. Deleting removes faces (and the vertices no face
// uses any more), leaving holes; dissolving merges the faces around an element into one polygon,
// leaving no hole. Follows the modelling contract (core/modelling/mesh_arrays.h): the input is never
// changed, a refusal throws a one-line gps::Error naming the element (by its index in the input mesh),
// and the remaining vertices and faces compact in order. Selection after each: empty.
#include <array>
#include <string>
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Removes the faces; vertices no longer used by any face are removed too. Refuses a result that would
/// be non-manifold (two fans of faces left touching at one vertex, named by its input index) or empty.
Modelled delete_faces(const CovarianceMesh& mesh, const std::vector<int>& faces);

/// An operation's `result` with its `faces` then deleted as delete_faces does, its selection and vertex
/// origins (relative to the mesh before the operation) followed through both steps; the summary kept.
Modelled with_faces_deleted(const Modelled& result, const std::vector<int>& faces);

/// Removes the vertices and every face that uses one of them (then the vertices left unused).
Modelled delete_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices);

/// Removes every face that has one of the edges (then the vertices left unused). Refuses an edge that
/// is not in the mesh ("edge a–b is not in the mesh").
Modelled delete_edges(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges);

/// The three deletions made in `arrays` (a run of steps on arrays, core/modelling/operation_list.h),
/// each refusing what it refuses above: no selection, with `summary` saying what was removed.
std::vector<int> delete_faces_in(MeshArrays& arrays, const std::vector<int>& faces, std::string& summary);
std::vector<int> delete_vertices_in(MeshArrays& arrays, const std::vector<int>& vertices, std::string& summary);
std::vector<int> delete_edges_in(MeshArrays& arrays, const std::vector<std::array<int, 2>>& edges,
                                 std::string& summary);

/// Dissolves vertices: the faces around an interior vertex merge into one polygon without it; a
/// boundary vertex that lies in a single face is simply removed from that face. As Blender does, the
/// edges between two interior vertices dissolve first, and a vertex then left between two edges in a
/// line is removed from both faces, joining the edges (the vertices of a loop cut give back the faces
/// it cut). Refuses any other boundary vertex, and a result with a polygon of fewer than 3 corners or
/// with a vertex repeated.
Modelled dissolve_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices);

/// Dissolves interior edges: the two faces on each merge into one polygon (a chain of edges merges
/// several faces; the merged polygon keeps the index of the first of them and starts at its first
/// corner), and an end left between two edges in a line joins them, as Blender's Dissolve Edges does
/// (one edge of a cube gives a prism of 6 vertices; a loop cut's edges give back the faces it cut). Refuses boundary
/// edges, an edge whose removal would cut a hole into a face, and a result with a vertex repeated in a face.
Modelled dissolve_edges(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges);

}  // namespace gps
