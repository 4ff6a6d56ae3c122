#include "core/modelling/affine_transform.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/modelling/operation_words.h"
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

int reverse_parts_within(MeshArrays& arrays, const std::vector<int>& moved) {
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
  int reversed = 0;
  for (std::vector<int>& face : arrays.faces)
    if (!face.empty() && !part_stays[size_t(root(face[0]))]) {
      std::reverse(face.begin() + 1, face.end());
      ++reversed;
    }
  return reversed;
}

double strongest_stretch(const AffineMap& map) { return Eigen::JacobiSVD<Mat3>(map.linear).singularValues()[0]; }

CarriedGaussian carried_gaussian(const AffineMap& map, const Gaussian& g) {
  return carried_gaussian(map, g, strongest_stretch(map));
}

namespace {

// Whether the carried covariance `c` of `sigma` lies so far above the floor (stretch² · λ_min(Σ)) that
// the eigen-solves of carried_gaussian would find it there too, with neither solve: every eigenvalue
// of c is at least its lowest Gershgorin bound, λ_min(Σ) at most Σ's least diagonal entry, and a
// backward-stable solve of a 3×3 matrix errs by a few ε·‖c‖, far below the margin of 1e-9·‖c‖ kept.
bool clearly_above_floor(const Mat3& c, const Mat3& sigma, double stretch) {
  double lowest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    double radius = 0.0;
    for (int j = 0; j < 3; ++j)
      if (j != i) radius += std::abs(c(i, j));
    lowest = std::min(lowest, c(i, i) - radius);
  }
  constexpr double kMargin = 1e-9;
  const double thinnest_at_most = sigma.diagonal().minCoeff() + kMargin * 3.0 * sigma.cwiseAbs().maxCoeff();
  const double floor_at_most = stretch * stretch * thinnest_at_most * (1.0 + kMargin);
  return lowest - kMargin * 3.0 * c.cwiseAbs().maxCoeff() > floor_at_most;
}

}  // namespace

CarriedGaussian carried_gaussian(const AffineMap& map, const Gaussian& g, double strongest) {
  CarriedGaussian out{map.apply(g), false};
  const double stretch = kFlattestStretch * (strongest > 0 ? strongest : 1.0);
  if (clearly_above_floor(out.gaussian.covariance, g.covariance, stretch)) return out;
  const double thinnest = Eigen::SelfAdjointEigenSolver<Mat3>(g.covariance, Eigen::EigenvaluesOnly).eigenvalues()[0];
  const double floor = stretch * stretch * thinnest;
  // The eigenvectors only where the floor holds (the eigenvalues are the same either way).
  const Eigen::SelfAdjointEigenSolver<Mat3> values(out.gaussian.covariance, Eigen::EigenvaluesOnly);
  if (!(values.eigenvalues()[0] < floor)) return out;
  const Eigen::SelfAdjointEigenSolver<Mat3> carried(out.gaussian.covariance);
  const Mat3 c =
      carried.eigenvectors() * carried.eigenvalues().cwiseMax(floor).asDiagonal() * carried.eigenvectors().transpose();
  out.gaussian.covariance = 0.5 * (c + c.transpose());
  out.clamped = true;
  return out;
}

std::vector<int> transform_vertices_in_place(CovarianceMesh& mesh, const std::vector<int>& vertices,
                                             const AffineMap& map, std::string& summary) {
  if (!map.linear.allFinite() || !map.translation.allFinite()) throw Error("the map has a number that is not finite");
  std::vector<int> moved = vertices.empty() ? std::vector<int>() : sorted_vertices(mesh.n_vertices(), vertices);
  if (vertices.empty())
    for (size_t v = 0; v < mesh.n_vertices(); ++v) moved.push_back(int(v));
  std::vector<Gaussian> carried(moved.size());
  std::vector<char> clamped_at(moved.size(), 0), valid(moved.size(), 0);
  const double strongest = strongest_stretch(map);
#pragma omp parallel for if (moved.size() >= size_t(kParallelFaces))
  for (size_t i = 0; i < moved.size(); ++i) {
    const int v = moved[i];
    const CarriedGaussian g = carried_gaussian(map, {mesh.mean(size_t(v)), mesh.covariances[size_t(v)]}, strongest);
    valid[i] = position_problem(g.gaussian.mean).empty() && covariance_problem(g.gaussian.covariance).empty();
    carried[i] = g.gaussian;
    clamped_at[i] = g.clamped;
  }
  for (size_t i = 0; i < moved.size(); ++i) {  // the first vertex with a problem is named
    if (valid[i]) continue;
    std::string why = position_problem(carried[i].mean);
    if (why.empty()) why = covariance_problem(carried[i].covariance);
    throw Error("the result would not be a valid mesh: vertex " + std::to_string(moved[i]) + " " + why);
  }
  const size_t clamped = size_t(std::count(clamped_at.begin(), clamped_at.end(), 1));
  for (size_t i = 0; i < moved.size(); ++i) {
    mesh.set_mean(size_t(moved[i]), carried[i].mean);
    mesh.covariances[size_t(moved[i])] = carried[i].covariance;
  }
  const bool mirror = map.linear.determinant() < 0;
  int reversed = 0;
  if (mirror) {
    MeshArrays a = arrays_of(mesh);
    reversed = reverse_parts_within(a, moved);
    if (reversed > 0) mesh = build_mesh(a, mesh);
  }
  // Only a part moved whole turns inside out: one mirrored in part keeps its faces.
  const std::string mirrored =
      reversed > 0 ? " (mirrored: " + count_of(size_t(reversed), "face", "faces") + " reversed to stay outward)"
                   : " (mirrored in part: no part moved whole, no face reversed)";
  summary = "transformed " + count_of(moved.size(), "vertex", "vertices") + (mirror ? mirrored : "") +
            (clamped ? ", " + count_of(clamped, "Gaussian", "Gaussians") + " held at the flatness floor (" +
                           short_number(kFlattestStretch) + " of the map's strongest stretch)"
                     : "");
  return moved;
}

Modelled transform_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, const AffineMap& map) {
  Modelled out{mesh, {}, "", {}, {}};
  out.selection = transform_vertices_in_place(out.mesh, vertices, map, out.summary);
  return out;
}

}  // namespace gps
