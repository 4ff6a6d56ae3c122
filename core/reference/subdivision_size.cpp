#include "core/reference/subdivision_size.h"

namespace gps {

namespace {

// What subdivide() holds per vertex of its result (the 9D points of two levels, the mapped-back
// Gaussians, the mesh's vertices) and per face corner (the topology and connectivity of two levels,
// the mesh's half-edges): upper bounds of what it was measured to take.
constexpr double kBytesPerVertex = 160, kBytesPerCorner = 80;

}  // namespace

OutputSize subdivision_size(const CovarianceMesh& mesh, const SubdivisionOptions& options) {
  double vertices = double(mesh.n_vertices()), edges = double(mesh.n_edges()), faces = double(mesh.n_faces()),
         corners = double(mesh.n_corners());
  for (int level = 0; level < options.levels; ++level) {
    if (options.scheme == Scheme::loop) {
      // A vertex per vertex and per edge; every edge in 2, three inner edges and 4 triangles per triangle.
      vertices += edges;
      edges = 2 * edges + 3 * faces;
      faces *= 4;
      corners = 3 * faces;
    } else {
      // A vertex per vertex, edge and face; every edge in 2, a quad and an inner edge per corner.
      vertices += edges + faces;
      edges = 2 * edges + corners;
      faces = corners;
      corners = 4 * faces;
    }
  }
  return {vertices, faces, kBytesPerVertex * vertices + kBytesPerCorner * corners};
}

}  // namespace gps
