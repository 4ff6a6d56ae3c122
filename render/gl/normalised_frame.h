#pragma once
// The frame the GPU evaluates a mesh in: centred on its bounding box and scaled to a unit diagonal,
// so that float holds the Gaussians at any scale and position. GPS commutes with affine maps, so the
// surface drawn in the frame is the world surface mapped by x' = (x − centre) / unit.
#include <glm/glm.hpp>
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

struct NormalisedFrame {
  glm::dvec3 centre{0.0};
  double unit = 1.0;  // world length of one frame unit: the bounding box's diagonal

  /// The frame of `mesh`'s bounding box (the identity's scale for a mesh of one point).
  static NormalisedFrame of(const CovarianceMesh& mesh);
  /// `mesh` in the frame: means (μ − centre) / unit, covariances Σ / unit², computed in double.
  CovarianceMesh to_frame(const CovarianceMesh& mesh) const;
  /// The same for the `vertices` of `mesh` only, written into `framed` (the same topology).
  void to_frame(const CovarianceMesh& mesh, const std::vector<int>& vertices, CovarianceMesh& framed) const;
  /// World from frame as a matrix: x = centre + unit · x'.
  glm::dmat4 world_from_frame() const;
  glm::dvec3 to_world(const glm::dvec3& p) const { return centre + unit * p; }
};

}  // namespace gps
