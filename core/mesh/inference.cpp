#include "core/mesh/inference.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "core/support/error.h"

namespace gps {

namespace {

// The length of edge e: the distance between its ends' means.
double edge_length(const CovarianceMesh& m, size_t e) {
  const auto [a, b] = m.edge(e);
  return (m.mean(size_t(b)) - m.mean(size_t(a))).norm();
}

// The mean length of the mesh's edges (0 without edges).
double mean_edge_length(const CovarianceMesh& m) {
  double total = 0;
  for (size_t e = 0; e < m.n_edges(); ++e) total += edge_length(m, e);
  return m.n_edges() ? total / double(m.n_edges()) : 0.0;
}

// The mean edge length, checked: inferred covariances scale as its square, so where it would put them
// beyond covariance_problem's range [1e-100, 1e100] this throws gps::Error, with the mesh unchanged.
double checked_edge_length(const CovarianceMesh& m) {
  const double length = mean_edge_length(m);
  if (length == 0 || (length >= 1e-45 && length <= 1e45)) return length;
  char shown[32];
  std::snprintf(shown, sizeof shown, "%.3g", length);
  throw Error(std::string("the mesh is too ") + (length < 1 ? "small" : "large") +
              " for covariances inferred from its edges (" + shown + " long on average; its covariances would be " +
              (length < 1 ? "under 1e-100" : "over 1e100") + "): scale it to edges between 1e-45 and 1e45");
}

}  // namespace

void infer_covariances(CovarianceMesh& m, double bias, const ElementNames& names) {
  if (!(bias > 0)) throw usage_error("the inference bias must be positive, got " + std::to_string(bias));
  const double length = checked_edge_length(m);
  std::vector<Vec3> p;
  // The precision of face f's points, or false where the face is degenerate.
  const auto face_precision = [&](size_t f, Mat3& inv) {
    p.clear();
    Vec3 centre = Vec3::Zero();
    for (const int v : m.face(f)) {
      p.push_back(m.mean(size_t(v)));
      centre += p.back();
    }
    centre /= double(p.size());
    Mat3 c = Mat3::Zero();
    for (const Vec3& x : p) c += (x - centre) * (x - centre).transpose();
    c /= double(p.size());
    const double lambda_max = Eigen::SelfAdjointEigenSolver<Mat3>(c, Eigen::EigenvaluesOnly).eigenvalues()(2);
    if (!(lambda_max > 0)) return false;
    c += bias * lambda_max * Mat3::Identity();
    inv = Eigen::LLT<Mat3>(c).solve(Mat3::Identity());
    return true;
  };
  // Every face is checked before the covariances change, which then hold the summed precisions: no
  // second array of a matrix per vertex, and the mesh is left as it was when a face is degenerate.
  Mat3 inv;
  for (size_t f = 0; f < m.n_faces(); ++f)
    if (!face_precision(f, inv)) throw Error(names.face(int(f)) + " is degenerate (all its vertices coincide)");
  std::vector<Mat3>& precision = m.covariances;
  precision.assign(m.n_vertices(), Mat3::Zero());
  for (size_t f = 0; f < m.n_faces(); ++f) {
    face_precision(f, inv);
    for (const int v : m.face(f)) precision[size_t(v)] += inv;
  }
  // An isolated vertex has no faces to infer from: σ = half the mesh's mean edge length.
  const double sigma = length > 0 ? 0.5 * length : 1.0;
  for (size_t i = 0; i < m.n_vertices(); ++i) {
    const Eigen::LLT<Mat3> llt{Mat3(precision[i])};
    if (llt.info() != Eigen::Success) {
      m.covariances[i] = sigma * sigma * Mat3::Identity();
      continue;
    }
    const Mat3 cov = llt.solve(Mat3::Identity());
    m.covariances[i] = 0.5 * (cov + cov.transpose());
  }
}

void isotropic_covariances(CovarianceMesh& m, double s) {
  if (!(s > 0)) throw usage_error("the isotropic scale must be positive, got " + std::to_string(s));
  checked_edge_length(m);
  std::vector<double> sum(m.n_vertices(), 0.0);
  std::vector<int> count(m.n_vertices(), 0);
  double total = 0;
  for (size_t e = 0; e < m.n_edges(); ++e) {
    const double l = edge_length(m, e);
    const auto [a, b] = m.edge(e);
    sum[size_t(a)] += l, sum[size_t(b)] += l;
    ++count[size_t(a)], ++count[size_t(b)];
    total += l;
  }
  const double fallback = m.n_edges() ? total / double(m.n_edges()) : 1.0;
  for (size_t i = 0; i < m.n_vertices(); ++i) {
    const double l = count[i] && sum[i] > 0 ? sum[i] / count[i] : fallback;
    m.covariances[i] = (s * l) * (s * l) * Mat3::Identity();
  }
}

}  // namespace gps
