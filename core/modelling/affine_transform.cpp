#include "core/modelling/affine_transform.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "core/support/error.h"

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

void reverse_parts_within(MeshArrays& arrays, const std::vector<int>& moved) {
  // Parts by union-find over the faces' corners; a part is reversed when no vertex of it stays.
  std::vector<int> parent(size_t(arrays.n_vertices()));
  for (size_t v = 0; v < parent.size(); ++v) parent[v] = int(v);
  const auto root = [&](int v) {
    while (parent[size_t(v)] != v) v = parent[size_t(v)] = parent[size_t(parent[size_t(v)])];
    return v;
  };
  for (const std::vector<int>& face : arrays.faces)
    for (size_t k = 1; k < face.size(); ++k) parent[size_t(root(face[k]))] = root(face[0]);
  std::vector<char> is_moved(parent.size(), 0), part_stays(parent.size(), 0);
  for (const int v : moved) is_moved[size_t(v)] = 1;
  for (const std::vector<int>& face : arrays.faces)
    for (const int v : face)
      if (!is_moved[size_t(v)]) part_stays[size_t(root(v))] = 1;
  for (std::vector<int>& face : arrays.faces)
    if (!face.empty() && !part_stays[size_t(root(face[0]))]) std::reverse(face.begin() + 1, face.end());
}

Modelled transform_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, const AffineMap& map) {
  if (!map.linear.allFinite() || !map.translation.allFinite()) throw Error("the map has a number that is not finite");
  // Flattening relative to its own size (a huge or tiny uniform scale is not; its results are checked
  // below): the ratio of its smallest to its largest singular value.
  const Vec3 stretch = Eigen::JacobiSVD<Mat3>(map.linear).singularValues();
  if (!(stretch[2] > 0)) throw Error("the map is singular (determinant 0: it would flatten the Gaussians)");
  if (!(stretch[2] > 1e-12 * stretch[0])) {
    std::ostringstream text;
    text << "the map stretches one direction " << std::setprecision(3) << stretch[0] / stretch[2]
         << " times as much as another (more than 1e12: it would flatten the Gaussians)";
    throw Error(text.str());
  }
  MeshArrays a = arrays_of(mesh);
  std::vector<int> moved = vertices.empty() ? std::vector<int>() : sorted_vertices(a, vertices);
  if (vertices.empty())
    for (int v = 0; v < a.n_vertices(); ++v) moved.push_back(v);
  for (int v : moved) {
    const Gaussian g = map.apply(a.gaussian(v));
    a.means[size_t(v)] = g.mean;
    a.covariances[size_t(v)] = g.covariance;
  }
  const bool mirror = map.linear.determinant() < 0;
  if (mirror) reverse_parts_within(a, moved);
  Modelled out{build_mesh(a), moved, ""};
  out.summary = "transformed " + std::to_string(moved.size()) + (moved.size() == 1 ? " vertex" : " vertices") +
                (mirror ? " (mirrored: their faces reversed to stay outward)" : "");
  return out;
}

}  // namespace gps
