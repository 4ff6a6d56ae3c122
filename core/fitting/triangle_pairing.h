#pragma once
// Pairing a triangle mesh's triangles into quads, for Catmull-Clark modelling from a simplified scan
// (as Blender's Tris to Quads): the mesh keeps its vertices, Gaussians and creases.
#include "core/mesh/covariance_mesh.h"

namespace gps {

struct TrianglePairing {
  double max_corner_deviation_degrees = 45;  // the most a quad's corner angle may be off 90°
  double max_fold_degrees = 30;              // the most the two triangles' normals may differ
};

/// Joins pairs of triangles across an interior edge without a crease into quads, greedily, the
/// squarest and flattest first (each pair scored by its worst corner's deviation from 90° plus its
/// fold), each triangle at most once; a quad takes the place of the first of its two triangles and
/// keeps their orientation. Faces of other sizes and unpaired triangles stay. Returns the quads made.
size_t pair_triangles(CovarianceMesh& mesh, const TrianglePairing& limits = {});

}  // namespace gps
