#include "render/gl/normalised_frame.h"

#include <cmath>

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

CovarianceMesh NormalisedFrame::to_frame(const CovarianceMesh& mesh) const {
  CovarianceMesh out = mesh;
  std::vector<int> all(mesh.n_vertices());
  for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
  to_frame(mesh, all, out);
  return out;
}

void NormalisedFrame::to_frame(const CovarianceMesh& mesh, const std::vector<int>& vertices,
                               CovarianceMesh& framed) const {
  const Vec3 c(centre.x, centre.y, centre.z);
  const double s = 1.0 / unit;
  for (const int v : vertices) {
    const size_t i = size_t(v);
    framed.set_mean(i, (mesh.mean(i) - c) * s);
    framed.set_covariance(i, mesh.covariance(i) * (s * s));
  }
}

glm::dmat4 NormalisedFrame::world_from_frame() const {
  glm::dmat4 m(unit);
  m[3] = glm::dvec4(centre, 1.0);
  return m;
}

}  // namespace gps
