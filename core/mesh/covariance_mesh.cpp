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

#include "core/mesh/connectivity_update.h"
#include "core/mesh/dual_map.h"
#include "core/support/error.h"

namespace gps {

bool CovarianceMesh::is_boundary_vertex(size_t v) const {
  return connectivity().valence(int(v)) != connectivity().n_vertex_faces(int(v));
}

bool is_spd(const Mat3& c) {
  if (!c.allFinite()) return false;
  const double scale = c.cwiseAbs().maxCoeff();
  if (!(scale > 0)) return false;
  if ((c - c.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) return false;
  const Eigen::LLT<Mat3> llt(0.5 * (c + c.transpose()));
  return llt.info() == Eigen::Success;
}

// make_covariance_mesh's work, the one place a mesh's private parts are filled.
class CovarianceMeshAssembly {
public:
  // `return_pages`: hand the faces' temporary arrays back to the system before the covariances are
  // made, as a reader wants (its memory is that of the mesh it read); a modelling operation's result,
  // whose covariances are given, skips it and reuses the pages. `c`: the connectivity of `t`, or null;
  // `checked`: `t`'s faces and `c` are known to make a manifold (updated_connectivity vouched for them).
  // `origin`: where the shape came from, where known.
  static CovarianceMesh assemble(std::vector<Vec3>&& means, std::vector<Mat3>&& covariances, PolygonTopology&& t,
                                 MeshConnectivity* c, const std::string& source, const ElementNames& names,
                                 bool return_pages, bool checked = false, ShapeOrigin* origin = nullptr) {
    if (means.size() != covariances.size() && !covariances.empty())
      throw Error(source + ": " + std::to_string(means.size()) + " vertices but " + std::to_string(covariances.size()) +
                  " covariances");
    t.n_vertices = int(means.size());
    for (size_t i = 0; i < means.size(); ++i)
      if (!means[i].allFinite())
        throw Error(source + ": " + names.vertex(int(i)) + " has a position that is not finite");
    if (!checked) check_faces(t, source, names);
    // A reader's arrays grew by doubling: the mesh keeps them at their size, copied before the
    // connectivity's larger temporaries exist. A modelling operation's room to grow (arrays_of) is
    // kept rather than copied away.
    const auto fit = [](auto& array) {
      if (array.capacity() > array.size() + array.size() / 8) array.shrink_to_fit();
    };
    fit(means);
    fit(t.offsets);
    fit(t.verts);
    CovarianceMesh m;
    auto shape = new_mesh_shape();
    // The checks before the vertices' rows: their temporaries and the rows are not held at once.
    shape->connectivity = c ? std::move(*c) : edge_connectivity(t);
    if (!checked) check_manifold(t, shape->connectivity, source, names);
    if (!c) add_vertex_rows(t, shape->connectivity);
#ifdef __GLIBC__
    // connectivity_of's temporaries may lie below the top of the heap, which free() does not hand
    // back: their pages are returned before the covariances are made.
    if (return_pages) malloc_trim(0);
#endif
    m.means_ = std::move(means);
    shape->topology = std::move(t);
    if (origin) shape->origin = std::move(*origin);
    m.shape_ = std::move(shape);
    m.covariances = std::move(covariances);
    // Identity covariances are made once the temporary arrays are gone.
    if (m.covariances.empty()) m.covariances.assign(m.means_.size(), Mat3::Identity());
    return m;
  }

private:
  // Every face has at least three corners, each a vertex of the mesh, none twice.
  static void check_faces(const PolygonTopology& t, const std::string& source, const ElementNames& names) {
    std::vector<size_t> last_face(size_t(t.n_vertices), size_t(-1));  // the last face that used each vertex
    for (int f = 0; f < t.n_faces(); ++f) {
      const auto where = [&] { return source + ": " + names.face(f); };
      if (t.face_size(f) < 3)
        throw Error(where() + " has " + std::to_string(t.face_size(f)) + " vertices (at least 3 needed)");
      for (int k = t.offsets[size_t(f)]; k < t.offsets[size_t(f) + 1]; ++k) {
        const int i = t.verts[size_t(k)];
        if (i < 0 || i >= t.n_vertices)
          throw Error(where() + " refers to " + names.vertex(i) + ", but there are only " +
                      std::to_string(t.n_vertices) + " vertices");
        if (last_face[size_t(i)] == size_t(f)) throw Error(where() + " uses " + names.vertex(i) + " twice");
        last_face[size_t(i)] = size_t(f);
      }
    }
  }
};

CovarianceMesh make_covariance_mesh(const std::vector<Vec3>& means, const std::vector<Mat3>& covariances,
                                    const std::vector<std::vector<int>>& faces, const std::string& source) {
  return CovarianceMeshAssembly::assemble(std::vector<Vec3>(means), std::vector<Mat3>(covariances),
                                          polygon_topology(faces), nullptr, source, {}, covariances.empty());
}

CovarianceMesh make_covariance_mesh(std::vector<Vec3>&& means, std::vector<Mat3>&& covariances, PolygonTopology&& t,
                                    const std::string& source, const ElementNames& names) {
  return CovarianceMeshAssembly::assemble(std::move(means), std::move(covariances), std::move(t), nullptr, source,
                                          names, true);
}

CovarianceMesh make_covariance_mesh(std::vector<Vec3>&& means, std::vector<Mat3>&& covariances, PolygonTopology&& t,
                                    MeshConnectivity&& connectivity, const std::string& source) {
  return CovarianceMeshAssembly::assemble(std::move(means), std::move(covariances), std::move(t), &connectivity, source,
                                          {}, false);
}

CovarianceMesh make_covariance_mesh(const CovarianceMesh& before, std::vector<Vec3>&& means,
                                    std::vector<Mat3>&& covariances, PolygonTopology&& faces,
                                    const MeshOrigins& origins, const std::string& source) {
  faces.n_vertices = int(means.size());
  std::vector<int> continued;
  std::optional<MeshConnectivity> c =
      updated_connectivity(before.topology(), before.connectivity(), faces, origins, &continued);
  // The origin only where the update vouched for the result (else the mesh is built whole).
  ShapeOrigin origin;
  if (c) origin = {before.shape(), origins.vertices, std::move(continued)};
  return CovarianceMeshAssembly::assemble(std::move(means), std::move(covariances), std::move(faces), c ? &*c : nullptr,
                                          source, {}, false, c.has_value(), c ? &origin : nullptr);
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
  // A box per block of vertices on all cores, then joined (a minimum and a maximum in any order).
  constexpr int kBlocks = 16;
  const size_t n = m.n_vertices();
  std::array<Vec3, kBlocks> block_lo, block_hi;
  block_lo.fill(lo);
  block_hi.fill(hi);
#pragma omp parallel for schedule(static) if (n >= size_t(16 * kParallelFaces))
  for (int b = 0; b < kBlocks; ++b)
    for (size_t i = n * size_t(b) / kBlocks; i < n * size_t(b + 1) / kBlocks; ++i) {
      block_lo[size_t(b)] = block_lo[size_t(b)].cwiseMin(m.mean(i));
      block_hi[size_t(b)] = block_hi[size_t(b)].cwiseMax(m.mean(i));
    }
  for (int b = 0; b < kBlocks; ++b) {
    lo = lo.cwiseMin(block_lo[size_t(b)]);
    hi = hi.cwiseMax(block_hi[size_t(b)]);
  }
}

double bounding_box_diagonal(const CovarianceMesh& m) {
  Vec3 lo, hi;
  bounding_box(m, lo, hi);
  return (hi - lo).norm();
}

Vec3 evaluation_origin(const CovarianceMesh& mesh) {
  if (mesh.n_vertices() == 0) return Vec3::Zero();
  Vec3 lo, hi;
  bounding_box(mesh, lo, hi);
  const Vec3 centre = 0.5 * (lo + hi);
  return centre.norm() > (hi - lo).norm() ? centre : Vec3::Zero();
}

std::vector<Dual> base_points(const CovarianceMesh& mesh, const Vec3& origin) {
  std::vector<Dual> q(mesh.n_vertices());
#pragma omp parallel for if (q.size() >= 4096)
  for (size_t i = 0; i < q.size(); ++i) q[i] = to_dual(mesh.mean(i) - origin, mesh.covariance(i));
  return q;
}

}  // namespace gps
