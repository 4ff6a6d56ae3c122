#pragma once
// Bisecting a mesh by a plane, as Blender's Bisect does: every face the plane crosses is cut along it,
// so that the plane's trace becomes a chain of edges (a cut for later deletion, mirroring or creasing).
#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Cuts every face the plane through `point` with normal `normal` crosses. Each edge whose ends lie on
/// opposite sides gets a new vertex at the crossing parameter t of its means (d_a / (d_a − d_b) for
/// the ends' signed distances), with the Gaussian of the 9D blend (1 − t, t) of its ends; each crossed
/// face is split along the chords between its points on the plane (pairs along the plane's trace where
/// a concave face is crossed more than twice). Vertices on the plane (within 1e-9 of the mesh's
/// bounding-box diagonal) are used as they are, not duplicated. A crossed edge's crease goes to both
/// halves. On a mesh of triangles the quads a cut makes are split by their shorter diagonal, so that
/// the mesh stays Loop's. A split face keeps its index for its first piece; new vertices and pieces
/// are appended. Refuses a normal that is zero or not finite and a plane that crosses no face.
/// Selection: the vertices on the cut.
Modelled bisect(const CovarianceMesh& mesh, const Vec3& point, const Vec3& normal);

}  // namespace gps
