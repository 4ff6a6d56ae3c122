#pragma once
// Subdividing a covariance mesh as a modelling step: the whole mesh one GPS level finer (the same
// limit surface on a finer control mesh), or only chosen faces split in 9D, their neighbours kept
// conforming. Operations follow core/modelling/mesh_arrays.h's contract: the input is never changed,
// a refusal throws gps::Error, kept vertices and faces keep their indices, new ones are appended.
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/modelling/mesh_arrays.h"

namespace gps {

/// The whole mesh one GPS step finer by its own scheme (Loop for a mesh of triangles only, else
/// Catmull-Clark; the exact reference, core/reference/reference_subdivision.h): the refined mesh has
/// the same limit surface. Vertices and faces are numbered as the reference numbers them (the old
/// vertices first, at their indices). Selection: none (the old selection has no counterpart).
Modelled subdivide_all(const CovarianceMesh& mesh);

/// Only `faces` refined, in 9D. On a mesh of triangles only, each chosen triangle splits 1 → 4 at its
/// edges' 9D midpoints, and an unchosen neighbour triangle splits into 2, 3 or 4 triangles by the
/// midpoints on its edges (with two: the triangle at their common corner and the rest cut along its
/// shorter diagonal), so the mesh stays triangles. Otherwise each chosen n-gon splits into n
/// quads (corner, edge midpoint, face point: the 9D average of its corners, edge midpoint), and an
/// unchosen neighbour takes the midpoints on its edges as extra corners. New vertices: per chosen face
/// in ascending order, its face point (not for triangles), then the midpoints of its edges not made
/// yet, in corner order. A split face keeps its index for the piece at its corner 0; the other pieces
/// are appended. Selection: the vertices of the chosen faces' pieces. Refuses an empty or unknown face.
Modelled subdivide_faces(const CovarianceMesh& mesh, const std::vector<int>& faces);

}  // namespace gps
