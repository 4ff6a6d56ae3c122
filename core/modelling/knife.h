#pragma once
// Cutting a mesh along a path of points on its faces, as Blender's Knife does for points on the
// surface: the cut runs straight across each face between consecutive points and becomes a chain of
// edges (for creasing, extruding or deleting along it).
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Cuts the mesh along the path through `points`, each on a face (within 1e-4 of the mesh's
/// bounding-box diagonal). Between two consecutive points the cut follows the plane through both
/// that holds the surface's normals there (each the sum of the unit normals of the faces holding
/// the point): it leaves the first point along the segment and follows the plane's trace face by
/// face, wherever the surface bends it, to the second (the segment projected onto the faces it
/// crosses). Where it crosses an edge the edge gets split_edge's new vertex (add_edge_vertex: the
/// 9D blend at the crossing parameter of the edge's means, the crease on both halves); a crossing
/// or a point within 1/1000 of the edge's length from an end uses that vertex. Each face crossed is
/// split along the cut. A point inside a face between the path's ends becomes a vertex of that
/// face's cut, with the 9D blend of the face's corners by their mean value coordinates (Floater
/// 2003). A mesh has no dangling edges, so the path's first and last point, when inside a face, are
/// moved on along the cut (away from the rest of it) to where it leaves the face: every cut runs
/// from an edge or vertex to an edge or vertex. A path whose last point is its first (round three
/// points or more) cuts a loop. On a mesh of triangles the pieces (and the faces beside the path's
/// ends, which gain a corner) are triangulated, so that it stays Loop's. A split face keeps its
/// index for its first piece; new vertices (in the path's order) and pieces are appended. Refuses
/// fewer than two points, a point not on the mesh or not finite ("point 3 is not on the mesh",
/// numbered from 1), two consecutive points at one place, a segment along the normals (which no
/// such plane holds), a path that leaves the mesh at its boundary or whose plane's trace does not
/// reach the next point, one that crosses itself inside a face, and one along edges already there
/// only. Selection: the vertices on the cut.
Modelled knife(const CovarianceMesh& mesh, const std::vector<Vec3>& points);

}  // namespace gps
