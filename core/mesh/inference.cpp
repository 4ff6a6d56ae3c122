#include "core/mesh/inference.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "core/support/error.h"

namespace gps {

void infer_covariances(CovarianceMesh& m, double bias, const ElementNames& names) {
  if (!(bias > 0)) throw usage_error("the inference bias must be positive, got " + std::to_string(bias));
  std::vector<Vec3> p;
  // The precision of face f's points, or false where the face is degenerate.
  const auto face_precision = [&](PolyMesh::FaceHandle f, Mat3& inv) {
    p.clear();
    Vec3 centre = Vec3::Zero();
    for (const auto v : m.mesh.fv_range(f)) {
      p.push_back(to_vec3(m.mesh.point(v)));
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
  for (const auto f : m.mesh.faces())
    if (!face_precision(f, inv))
      throw Error(names.face(f.idx()) + " is degenerate (all its vertices coincide)");
  std::vector<Mat3>& precision = m.covariances;
  precision.assign(m.n_vertices(), Mat3::Zero());
  for (const auto f : m.mesh.faces()) {
    face_precision(f, inv);
    for (const auto v : m.mesh.fv_range(f)) precision[size_t(v.idx())] += inv;
  }
  // An isolated vertex has no faces to infer from: σ = half the mesh's mean edge length.
  double total = 0;
  for (const auto e : m.mesh.edges()) total += m.mesh.calc_edge_length(e);
  const double sigma = m.mesh.n_edges() && total > 0 ? 0.5 * total / double(m.mesh.n_edges()) : 1.0;
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
  std::vector<double> sum(m.n_vertices(), 0.0);
  std::vector<int> count(m.n_vertices(), 0);
  double total = 0;
  for (const auto e : m.mesh.edges()) {
    const double l = m.mesh.calc_edge_length(e);
    const int a = e.v0().idx(), b = e.v1().idx();
    sum[size_t(a)] += l, sum[size_t(b)] += l;
    ++count[size_t(a)], ++count[size_t(b)];
    total += l;
  }
  const double fallback = m.mesh.n_edges() ? total / double(m.mesh.n_edges()) : 1.0;
  for (size_t i = 0; i < m.n_vertices(); ++i) {
    const double l = count[i] && sum[i] > 0 ? sum[i] / count[i] : fallback;
    m.covariances[i] = (s * l) * (s * l) * Mat3::Identity();
  }
}

}  // namespace gps
