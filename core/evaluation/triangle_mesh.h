#pragma once
// A tessellated limit surface: triangles with per-vertex positions and normals, and its files.
#include <array>
#include <string>
#include <vector>

#include "core/mesh/linalg.h"

namespace gps {

struct TriangleMesh {
  std::vector<Vec3> positions, normals;
  std::vector<std::array<int, 3>> triangles;
};

/// Triangles whose positions are about `origin`: a surface evaluated about its mesh's evaluation origin
/// (core/mesh/covariance_mesh.h) and kept there, whose digits world coordinates far away would lose.
struct PlacedTriangles {
  TriangleMesh triangles;
  Vec3 origin = Vec3::Zero();
};

/// Gives each vertex whose normal is zero (none known there) the area-weighted normal of its triangles
/// (where they cancel, its largest triangle's; where all are degenerate, +z): a unit normal for every
/// vertex of a triangle; a vertex in none keeps its zero (no normal).
void fill_missing_normals(TriangleMesh& mesh);

/// Writes .ply (x y z nx ny nz; ASCII or binary little endian), .obj (v, vn, f v//vn) or .gltf/.glb
/// (POSITION and NORMAL, core/io/gltf_io.h), atomically.
void write_triangle_mesh(const std::string& path, const TriangleMesh& mesh, bool binary = false);

}  // namespace gps
