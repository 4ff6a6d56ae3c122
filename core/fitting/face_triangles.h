#pragma once
// A covariance mesh's faces themselves as triangles: the piecewise-linear control polygon that a
// limit surface is compared against (how far a simplified mesh lies from its input before any
// subdivision).
#include "core/evaluation/triangle_mesh.h"
#include "core/io/polygon_soup.h"
#include "core/mesh/covariance_mesh.h"

namespace gps {

/// Every face of `mesh` split into a fan of triangles from its first corner, on the means, with
/// each vertex's area-weighted normal.
TriangleMesh face_triangles(const CovarianceMesh& mesh);

/// The same for a reader's soup, whatever its topology (a scan that is not a manifold): each face a
/// fan from its first corner; a vertex on no face keeps a zero normal.
TriangleMesh face_triangles(const PolygonSoup& soup);

/// Per vertex of `fans` (face_triangles of a mesh or soup), the unit normal a fit turns its surface
/// toward: the area-weighted normal of its faces where every one of them lies within `max_angle`
/// degrees of it, else zero (a vertex on a sharp edge or corner, or on no face, whose faces give
/// no one direction).
std::vector<Vec3> smooth_vertex_normals(const TriangleMesh& fans, double max_angle = 30);

}  // namespace gps
