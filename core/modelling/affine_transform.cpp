#include "core/modelling/affine_transform.h"

#include <Eigen/LU>
#include <cmath>
#include <string>

#include "core/mesh/error.h"

namespace gps {

AffineMap AffineMap::about(const Vec3& pivot, const Mat3& linear) { return AffineMap{linear, pivot - linear * pivot}; }

AffineMap AffineMap::from_rows(const std::vector<double>& rows) {
  if (rows.size() != 16)
    throw Error("the matrix has " + std::to_string(rows.size()) + " numbers (16 needed: a row-major 4×4 affine map)");
  for (double x : rows)
    if (!std::isfinite(x)) throw Error("the matrix has a number that is not finite");
  if (rows[12] != 0 || rows[13] != 0 || rows[14] != 0 || rows[15] != 1)
    throw Error("the matrix's last row must be 0 0 0 1 (an affine map)");
  AffineMap map;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) map.linear(r, c) = rows[size_t(4 * r + c)];
    map.translation[r] = rows[size_t(4 * r + 3)];
  }
  return map;
}

Gaussian AffineMap::apply(const Gaussian& g) const {
  const Mat3 c = linear * g.covariance * linear.transpose();
  return {apply(g.mean), 0.5 * (c + c.transpose())};
}

Modelled transform_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, const AffineMap& map) {
  if (!map.linear.allFinite() || !map.translation.allFinite()) throw Error("the map has a number that is not finite");
  // Singular relative to its own size (a huge or tiny uniform scale is not; its results are checked below).
  const double scale = map.linear.cwiseAbs().maxCoeff();
  if (!(scale > 0) || !(std::abs((map.linear / scale).determinant()) > 1e-12))
    throw Error("the map is singular (it would flatten the Gaussians)");
  MeshArrays a = arrays_of(mesh);
  std::vector<int> moved = vertices.empty() ? std::vector<int>() : sorted_vertices(a, vertices);
  if (vertices.empty())
    for (int v = 0; v < a.n_vertices(); ++v) moved.push_back(v);
  for (int v : moved) {
    const Gaussian g = map.apply(a.gaussian(v));
    a.means[size_t(v)] = g.mean;
    a.covariances[size_t(v)] = g.covariance;
  }
  Modelled out{build_mesh(a), moved, ""};
  out.summary = "transformed " + std::to_string(moved.size()) + (moved.size() == 1 ? " vertex" : " vertices");
  return out;
}

}  // namespace gps
