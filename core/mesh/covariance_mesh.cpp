#include "core/mesh/covariance_mesh.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <algorithm>
#include <sstream>

#include "core/mesh/dual_map.h"
#include "core/support/error.h"
#include "core/mesh/mesh_connectivity.h"

namespace gps {

Vec3 CovarianceMesh::mean(size_t i) const { return to_vec3(mesh.point(PolyMesh::VertexHandle(int(i)))); }

void CovarianceMesh::set_mean(size_t i, const Vec3& mean) {
  mesh.set_point(PolyMesh::VertexHandle(int(i)), to_point(mean));
}

bool is_spd(const Mat3& c) {
  if (!c.allFinite()) return false;
  const double scale = c.cwiseAbs().maxCoeff();
  if (!(scale > 0)) return false;
  if ((c - c.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) return false;
  const Eigen::LLT<Mat3> llt(0.5 * (c + c.transpose()));
  return llt.info() == Eigen::Success;
}

namespace {

// make_covariance_mesh's work. `return_pages`: hand the faces' temporary arrays back to the system
// before the covariances are made, as a reader wants (its memory is that of the mesh it read); a
// modelling operation's result, whose covariances are given, skips it and reuses the pages.
CovarianceMesh assemble(std::vector<Vec3>&& means, std::vector<Mat3>&& covariances, PolygonTopology&& t,
                        const std::string& source, const ElementNames& names, bool return_pages) {
  if (means.size() != covariances.size() && !covariances.empty())
    throw Error(source + ": " + std::to_string(means.size()) + " vertices but " + std::to_string(covariances.size()) +
                " covariances");
  t.n_vertices = int(means.size());
  for (size_t i = 0; i < means.size(); ++i)
    if (!means[i].allFinite()) throw Error(source + ": " + names.vertex(int(i)) + " has a position that is not finite");
  {
    std::vector<size_t> last_face(means.size(), size_t(-1));  // the last face that used each vertex: repeats in O(1)
    for (int f = 0; f < t.n_faces(); ++f) {
      const auto where = [&] { return source + ": " + names.face(f); };
      if (t.face_size(f) < 3)
        throw Error(where() + " has " + std::to_string(t.face_size(f)) + " vertices (at least 3 needed)");
      for (int k = t.offsets[size_t(f)]; k < t.offsets[size_t(f) + 1]; ++k) {
        const int i = t.verts[size_t(k)];
        if (i < 0 || size_t(i) >= means.size())
          throw Error(where() + " refers to " + names.vertex(i) + ", but there are only " +
                      std::to_string(means.size()) + " vertices");
        if (last_face[size_t(i)] == size_t(f)) throw Error(where() + " uses " + names.vertex(i) + " twice");
        last_face[size_t(i)] = size_t(f);
      }
    }
  }
  CovarianceMesh m;
  m.covariances = std::move(covariances);
  m.mesh.reserve(means.size(), 0, 0);  // edges and faces: add_faces, at their exact counts
  for (const Vec3& p : means) m.mesh.add_vertex(to_point(p));
  const size_t n_vertices = means.size();
  std::vector<Vec3>().swap(means);
  add_faces(m.mesh, t, source, names);
  t = {};
#ifdef __GLIBC__
  // The temporaries above may lie below the top of the heap, which free() does not hand back:
  // their pages are returned before the covariances are made.
  if (return_pages) malloc_trim(0);
#endif
  // Identity covariances are made once the faces' temporary arrays are gone.
  if (m.covariances.empty()) m.covariances.assign(n_vertices, Mat3::Identity());
  return m;
}

}  // namespace

CovarianceMesh make_covariance_mesh(const std::vector<Vec3>& means, const std::vector<Mat3>& covariances,
                                    const std::vector<std::vector<int>>& faces, const std::string& source) {
  PolygonTopology t;
  size_t n_corners = 0;
  for (const auto& face : faces) n_corners += face.size();
  t.offsets.reserve(faces.size() + 1);
  t.verts.reserve(n_corners);
  for (const auto& face : faces) {
    t.verts.insert(t.verts.end(), face.begin(), face.end());
    t.offsets.push_back(int(t.verts.size()));
  }
  return assemble(std::vector<Vec3>(means), std::vector<Mat3>(covariances), std::move(t), source, {},
                  covariances.empty());
}

CovarianceMesh make_covariance_mesh(std::vector<Vec3>&& means, std::vector<Mat3>&& covariances, PolygonTopology&& t,
                                    const std::string& source, const ElementNames& names) {
  return assemble(std::move(means), std::move(covariances), std::move(t), source, names, true);
}

namespace {
std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
}  // namespace

std::string position_problem(const Vec3& mean) {
  if (!mean.allFinite()) return "has a position that is not finite";
  if (mean.cwiseAbs().maxCoeff() > kMaxPositionMagnitude)
    return "has a coordinate " + number(mean.cwiseAbs().maxCoeff()) + " beyond ±" + number(kMaxPositionMagnitude) +
           " (its products would overflow)";
  return "";
}

namespace {

// A sufficient test that spares the eigen-solve: Gershgorin's discs of the lower triangle (what the
// solver reads) lie inside the accepted range with a margin far above its rounding, so the
// Cholesky factorisation and the eigenvalues below would accept the matrix too.
bool clearly_acceptable(const Mat3& c, double scale) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (int i = 0; i < 3; ++i) {
    double radius = 0.0;
    for (int j = 0; j < 3; ++j)
      if (j != i) radius += std::abs(c(std::max(i, j), std::min(i, j)));
    lo = std::min(lo, c(i, i) - radius);
    hi = std::max(hi, c(i, i) + radius);
  }
  return lo >= 1e-6 * scale && lo >= 2.0 * kMinCovarianceEigenvalue && hi <= 0.5 * kMaxCovarianceEigenvalue;
}

}  // namespace

std::string covariance_problem(const Mat3& c) {
  if (!c.allFinite()) return "has a covariance that is not finite";
  const double scale = c.cwiseAbs().maxCoeff();
  if (!(scale > 0)) return "has a covariance that is zero";
  if ((c - c.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) return "has a covariance that is not symmetric";
  if (clearly_acceptable(c, scale)) return "";
  const Vec3 eigenvalues = Eigen::SelfAdjointEigenSolver<Mat3>(c, Eigen::EigenvaluesOnly).eigenvalues();
  // Named by its smallest eigenvalue: also where a Cholesky factorisation succeeds but rounding leaves
  // that eigenvalue at or below zero.
  if (!is_spd(c) || !(eigenvalues(0) > 0))
    return "has a covariance that is not positive definite (eigenvalue " + number(eigenvalues(0)) + ")";
  if (eigenvalues(0) < kMinCovarianceEigenvalue)
    return "has a covariance eigenvalue " + number(eigenvalues(0)) + " below " + number(kMinCovarianceEigenvalue) +
           (eigenvalues(0) < std::numeric_limits<double>::min() ? " (subnormal: underflows)" : "") +
           " (its inverse would overflow)";
  if (eigenvalues(2) > kMaxCovarianceEigenvalue)
    return "has a covariance eigenvalue " + number(eigenvalues(2)) + " above " + number(kMaxCovarianceEigenvalue) +
           " (its inverse would underflow)";
  return "";
}

std::string gaussians_problem(const CovarianceMesh& m, const ElementNames& names) {
  for (size_t i = 0; i < m.n_vertices(); ++i) {
    std::string why = position_problem(m.mean(i));
    if (why.empty()) why = covariance_problem(m.covariances[i]);
    if (!why.empty()) return names.vertex(int(i)) + " " + why;
  }
  return "";
}

void validate_gaussians(const CovarianceMesh& m, const std::string& source, const ElementNames& names) {
  if (const std::string why = gaussians_problem(m, names); !why.empty()) throw Error(source + ": " + why);
}

void bounding_box(const CovarianceMesh& m, Vec3& lo, Vec3& hi) {
  lo = hi = m.n_vertices() == 0 ? Vec3::Zero() : m.mean(0);
  for (size_t i = 1; i < m.n_vertices(); ++i) {
    lo = lo.cwiseMin(m.mean(i));
    hi = hi.cwiseMax(m.mean(i));
  }
}

double bounding_box_diagonal(const CovarianceMesh& m) {
  Vec3 lo, hi;
  bounding_box(m, lo, hi);
  return (hi - lo).norm();
}

std::vector<Dual> base_points(const CovarianceMesh& mesh) {
  std::vector<Dual> q(mesh.n_vertices());
#pragma omp parallel for if (q.size() >= 4096)
  for (size_t i = 0; i < q.size(); ++i) q[i] = to_dual(mesh.mean(i), mesh.covariance(i));
  return q;
}

}  // namespace gps
