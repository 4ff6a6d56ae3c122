#pragma once
// A mesh as a reader produced it, before it becomes a CovarianceMesh: positions, optional
// covariances and faces as vertex-index lists, with nothing yet checked about the topology.
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/covariance_mesh.h"

#include "core/mesh/linalg.h"
#include "core/mesh/mesh_connectivity.h"

namespace gps {

struct PolygonSoup {
  std::vector<Vec3> positions;
  std::vector<Mat3> covariances;  // one per position, or empty for a plain mesh (inferred later)
  PolygonTopology faces;          // its n_vertices is not kept: positions.size() is the count
  Sharpness sharpness;            // creases on edges of the faces and corners, by vertex index
  // What the reader read leniently, a line each naming the file (a tag repeated with another value,
  // the later kept): for the caller to show, as warnings rather than refusals.
  std::vector<std::string> notes;
};

/// The undirected edges of the faces, each as (min << 32 | max) of its vertices (soup_edge_key),
/// sorted for std::binary_search: for a reader to check that its creases lie on edges, in 8 bytes
/// per face corner.
inline uint64_t soup_edge_key(int a, int b) {
  return uint64_t(uint32_t(a < b ? a : b)) << 32 | uint32_t(a < b ? b : a);
}
inline std::vector<uint64_t> soup_edge_keys(const PolygonTopology& faces) {
  std::vector<uint64_t> keys;
  keys.reserve(faces.verts.size());
  for (int f = 0; f < faces.n_faces(); ++f)
    for (int k = faces.offsets[size_t(f)]; k < faces.offsets[size_t(f) + 1]; ++k) {
      const int next = k + 1 == faces.offsets[size_t(f) + 1] ? faces.offsets[size_t(f)] : k + 1;
      keys.push_back(soup_edge_key(faces.verts[size_t(k)], faces.verts[size_t(next)]));
    }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

/// Corners a reader holds whatever they are: a soup this small is read whole, so that the repair can
/// mend the fins and duplicates that put more corners on its vertices than a manifold mesh has.
inline constexpr size_t kCornersReadWhole = size_t(1) << 20;

/// Whether `corners` face corners on `n_vertices` vertices are more than a manifold mesh can have
/// (each directed edge in one face at most: n(n − 1)), as one face repeated makes them, and past
/// kCornersReadWhole: a reader stops there rather than hold the rest.
inline bool exceeds_manifold_corners(size_t corners, size_t n_vertices) {
  const double n = double(n_vertices);
  return corners > kCornersReadWhole && double(corners) > n * (n - 1);
}

/// The CovarianceMesh of a soup, its arrays taken over (make_covariance_mesh: throws gps::Error naming
/// `source` and the face or vertex, as `names` names it, where the topology is not a manifold polygon mesh).
inline CovarianceMesh mesh_of_soup(PolygonSoup&& soup, const std::string& source, const ElementNames& names = {}) {
  if (soup.faces.n_faces() == 0) throw Error(source + ": the mesh has no faces");
  CovarianceMesh mesh = make_covariance_mesh(std::move(soup.positions), std::move(soup.covariances),
                                             std::move(soup.faces), source, names);
  mesh.sharpness = std::move(soup.sharpness);
  return mesh;
}

}  // namespace gps
