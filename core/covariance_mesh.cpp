#include "core/covariance_mesh.h"

#include <Eigen/Cholesky>
#include <iostream>
#include <algorithm>
#include <sstream>

#include "core/dual_map.h"
#include "core/error.h"

namespace gps {

namespace {
// Sends std::cerr to nowhere while alive.
class CerrSilencer {
public:
  CerrSilencer() : old_(std::cerr.rdbuf(sink_.rdbuf())) {}
  ~CerrSilencer() { std::cerr.rdbuf(old_); }
  CerrSilencer(const CerrSilencer&) = delete;
  CerrSilencer& operator=(const CerrSilencer&) = delete;

private:
  std::ostringstream sink_;
  std::streambuf* old_;
};
}  // namespace

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

CovarianceMesh make_covariance_mesh(const std::vector<Vec3>& means, const std::vector<Mat3>& covariances,
                                    const std::vector<std::vector<int>>& faces, const std::string& source) {
  if (means.size() != covariances.size())
    throw Error(source + ": " + std::to_string(means.size()) + " vertices but " +
                std::to_string(covariances.size()) + " covariances");
  CovarianceMesh m;
  m.covariances = covariances;
  std::vector<PolyMesh::VertexHandle> handles;
  handles.reserve(means.size());
  m.mesh.reserve(means.size(), 2 * faces.size() + means.size(), faces.size());
  for (const Vec3& p : means) handles.push_back(m.mesh.add_vertex(to_point(p)));
  std::vector<PolyMesh::VertexHandle> fv;
  // OpenMesh prints to std::cerr and returns an invalid handle on complex (non-manifold) input.
  const CerrSilencer silence_openmesh;
  for (size_t f = 0; f < faces.size(); ++f) {
    const auto& face = faces[f];
    const auto where = [&] { return source + ": face " + std::to_string(f); };
    if (face.size() < 3) throw Error(where() + " has " + std::to_string(face.size()) + " vertices (at least 3 needed)");
    fv.clear();
    for (int i : face) {
      if (i < 0 || size_t(i) >= means.size())
        throw Error(where() + " refers to vertex " + std::to_string(i) + ", but there are only " +
                    std::to_string(means.size()) + " vertices");
      if (std::count(face.begin(), face.end(), i) > 1) throw Error(where() + " uses vertex " + std::to_string(i) + " twice");
      fv.push_back(handles[size_t(i)]);
    }
    const auto fh = m.mesh.add_face(fv);
    if (!fh.is_valid())
      throw Error(where() + " makes the mesh non-manifold (an edge with more than two faces or a flipped face)");
  }
  for (const auto vh : m.mesh.vertices()) {
    if (!m.mesh.is_manifold(vh))
      throw Error(source + ": vertex " + std::to_string(vh.idx()) + " is non-manifold (its faces do not form one fan)");
  }
  return m;
}

void validate_gaussians(const CovarianceMesh& m, const std::string& source) {
  for (size_t i = 0; i < m.n_vertices(); ++i) {
    if (!m.mean(i).allFinite())
      throw Error(source + ": vertex " + std::to_string(i) + " has a position that is not finite");
    if (!is_spd(m.covariances[i]))
      throw Error(source + ": vertex " + std::to_string(i) +
                  " has a covariance that is not symmetric positive definite");
  }
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
