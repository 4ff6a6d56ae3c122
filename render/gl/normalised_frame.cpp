#include "render/gl/normalised_frame.h"

#include <cmath>

#include "core/mesh/mesh_connectivity.h"

namespace gps {

NormalisedFrame NormalisedFrame::of(const CovarianceMesh& mesh) {
  NormalisedFrame f;
  if (mesh.n_vertices() == 0) return f;
  Vec3 lo, hi;
  bounding_box(mesh, lo, hi);
  const Vec3 c = 0.5 * (lo + hi);
  f.centre = glm::dvec3(c.x(), c.y(), c.z());
  const double diagonal = (hi - lo).norm();
  if (std::isfinite(diagonal) && diagonal > 0.0) f.unit = diagonal;
  return f;
}

NormalisedFrame NormalisedFrame::following(const CovarianceMesh& mesh) const {
  const NormalisedFrame own = of(mesh);
  if (turned() && mesh.n_vertices() > 0) {  // the mesh's box along this frame's axes, in its units
    Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
    for (size_t v = 0; v < mesh.n_vertices(); ++v) {
      const Vec3 m = mean_in_frame(mesh.mean(v));
      lo = lo.cwiseMin(m), hi = hi.cwiseMax(m);
    }
    const double across = (hi - lo).norm();
    const bool near = (0.5 * (lo + hi)).norm() <= 0.1 && across <= 1.25 && 1.0 <= 1.25 * across;
    return near ? *this : own;
  }
  const bool near =
      glm::distance(own.centre, centre) <= 0.1 * unit && own.unit <= 1.25 * unit && unit <= 1.25 * own.unit;
  return near ? *this : own;
}

Vec3 NormalisedFrame::mean_in_frame(const Vec3& mean) const {
  const Vec3 m = (mean - Vec3(centre.x, centre.y, centre.z)) * (1.0 / unit);
  if (!turned()) return m;
  const glm::dvec3 f = glm::transpose(rotation) * glm::dvec3(m.x(), m.y(), m.z());
  return Vec3(f.x, f.y, f.z);
}

Mat3 NormalisedFrame::covariance_in_frame(const Mat3& covariance) const {
  const double s = 1.0 / unit;
  if (!turned()) return covariance * (s * s);
  const Mat3 r = rotation_matrix();
  const Mat3 turned_covariance = r.transpose() * covariance * r;
  return 0.5 * (turned_covariance + turned_covariance.transpose()) * (s * s);
}

Mat3 NormalisedFrame::rotation_matrix() const {
  Mat3 r;  // glm is column-major: rotation[column][row]
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) r(k, c) = rotation[c][k];
  return r;
}

glm::dvec3 NormalisedFrame::to_frame(const glm::dvec3& world) const {
  const Vec3 m = mean_in_frame(Vec3(world.x, world.y, world.z));
  return glm::dvec3(m.x(), m.y(), m.z());
}

CovarianceMesh NormalisedFrame::to_frame(const CovarianceMesh& mesh) const {
  CovarianceMesh out = mesh;
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    out.set_mean(i, mean_in_frame(mesh.mean(i)));
    out.set_covariance(i, covariance_in_frame(mesh.covariance(i)));
  }
  return out;
}

FramedGaussians NormalisedFrame::gaussians_in_frame(const CovarianceMesh& mesh) const {
  FramedGaussians framed;
  const size_t n = mesh.n_vertices();
  framed.means.resize(n);
  framed.covariances.resize(n);
  const FrameMap map(*this);
#pragma omp parallel for schedule(static) if (n >= size_t(kParallelFaces))
  for (size_t i = 0; i < n; ++i) {
    framed.means[i] = map.mean(mesh.mean(i));
    framed.covariances[i] = map.covariance(mesh.covariance(i));
  }
  return framed;
}

std::vector<int> NormalisedFrame::to_frame(const CovarianceMesh& mesh, const std::vector<int>& vertices,
                                           FramedGaussians& framed) const {
  std::vector<int> changed;
  changed.reserve(vertices.size());
  for (const int v : vertices) {
    const Vec3 mean = mean_in_frame(mesh.mean(size_t(v)));
    const Mat3 covariance = covariance_in_frame(mesh.covariance(size_t(v)));
    if (mean == framed.means[size_t(v)] && covariance == framed.covariances[size_t(v)]) continue;
    framed.means[size_t(v)] = mean;
    framed.covariances[size_t(v)] = covariance;
    changed.push_back(v);
  }
  return changed;
}

std::vector<int> changed_gaussians(const FramedGaussians& before, const CovarianceMesh& mesh,
                                   const NormalisedFrame& frame, const std::vector<int>& origin,
                                   FramedGaussians& framed) {
  const size_t n = mesh.n_vertices();
  framed.means.resize(n);
  framed.covariances.resize(n);
  // Framed and compared on all cores, then listed in order.
  std::vector<char> differs(n);
  const FrameMap map(frame);
#pragma omp parallel for schedule(static) if (n >= size_t(kParallelFaces))
  for (size_t v = 0; v < n; ++v) {
    const Vec3 mean = map.mean(mesh.mean(v));
    const Mat3 covariance = map.covariance(mesh.covariance(v));
    const size_t o = origin.empty() ? v : size_t(origin[v]);  // −1: past every vertex
    differs[v] = o >= before.n_vertices() || mean != before.means[o] || covariance != before.covariances[o];
    framed.means[v] = mean;
    framed.covariances[v] = covariance;
  }
  std::vector<int> changed;
  for (size_t v = 0; v < n; ++v)
    if (differs[v]) changed.push_back(int(v));
  return changed;
}

glm::dmat4 NormalisedFrame::world_from_frame() const {
  glm::dmat4 m(unit * rotation);
  m[3] = glm::dvec4(centre, 1.0);
  return m;
}

}  // namespace gps
