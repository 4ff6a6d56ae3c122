#include "view/picking.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>

namespace gps {

int pick_vertex(const Camera& camera, int width, int height, glm::vec2 pixel, const CovarianceMesh& mesh, float radius,
                const std::vector<char>* hidden) {
  NearestProjected nearest(camera, width, height, pixel, radius, 0.5f);
  for (size_t i = 0; i < mesh.n_vertices(); ++i)
    if (!hidden || i >= hidden->size() || !(*hidden)[i]) nearest.consider(int(i), mesh.mean(i));
  return nearest.best();
}

int pick_ellipsoid(const Camera& camera, int width, int height, glm::vec2 pixel, const CovarianceMesh& mesh,
                   double k_sigma, const std::vector<int>* candidates) {
  const Ray ray = pixel_ray(camera, width, height, pixel);
  const Vec3 origin = to_vec(ray.origin), d = to_vec(ray.direction);
  int best = -1;
  double best_t = std::numeric_limits<double>::infinity();
  const size_t n = candidates ? candidates->size() : mesh.n_vertices();
  for (size_t k = 0; k < n; ++k) {
    const size_t i = candidates ? size_t((*candidates)[k]) : k;
    if (i >= mesh.n_vertices()) continue;
    // |o + t·d|²_{Σ⁻¹} = k² with o = origin − μ: a t² + 2 b t + c = 0, Σ⁻¹ applied by an LDLᵀ solve.
    const Eigen::LDLT<Mat3> ldlt(mesh.covariance(i));
    const Vec3 o = origin - mesh.mean(i);
    const Vec3 inv_d = ldlt.solve(d), inv_o = ldlt.solve(o);
    const double a = d.dot(inv_d), b = o.dot(inv_d), c = o.dot(inv_o) - k_sigma * k_sigma;
    const double discriminant = b * b - a * c;
    if (!(a > 0) || !(discriminant >= 0)) continue;
    const double root = std::sqrt(discriminant);
    const double t = (-b - root) / a > 0 ? (-b - root) / a : (-b + root) / a;  // the eye may be inside
    if (t > 0 && t < best_t) best_t = t, best = int(i);
  }
  return best;
}

}  // namespace gps
