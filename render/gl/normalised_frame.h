#pragma once
// The frame the GPU evaluates a mesh in: centred on its bounding box and scaled to a unit diagonal,
// so that float holds the Gaussians at any scale and position. GPS commutes with affine maps, so the
// surface drawn in the frame is the world surface mapped by x' = rotationᵀ (x − centre) / unit. The
// rotation is the identity but where the frame moved with a mesh turned whole (render/gl/moved_frame.h).
#include <glm/glm.hpp>
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

/// The means and covariances of a mesh's vertices in a frame, without its topology: what the GPU and
/// the overlays take, kept without a copy of the mesh's connectivity.
struct FramedGaussians {
  std::vector<Vec3> means;
  std::vector<Mat3> covariances;

  size_t n_vertices() const { return means.size(); }
  const Vec3& mean(size_t v) const { return means[v]; }
  const Mat3& covariance(size_t v) const { return covariances[v]; }
};

struct NormalisedFrame {
  glm::dvec3 centre{0.0};
  double unit = 1.0;  // world length of one frame unit: the bounding box's diagonal
  glm::dmat3 rotation{1.0};  // the frame's axes in the world (columns), orthonormal, determinant 1

  bool operator==(const NormalisedFrame&) const = default;

  /// The frame of `mesh`'s bounding box (the identity's scale for a mesh of one point).
  static NormalisedFrame of(const CovarianceMesh& mesh);
  /// The frame to show `mesh` in after a change: this one while the mesh's own frame lies near it
  /// (its centre within a tenth of this unit, its unit within a factor of 1.25; for a turned frame,
  /// the mesh's box in this frame's axes), else the mesh's own.
  /// A renderer that keeps its frame keeps its evaluated output where a change did not reach
  /// (SurfaceRenderer::set_mesh with a PlanChange); an extrude past the bounding box would otherwise
  /// change the frame, and everything would be evaluated again.
  NormalisedFrame following(const CovarianceMesh& mesh) const;
  /// `mesh` in the frame: means (μ − centre) / unit, covariances Σ / unit², computed in double.
  CovarianceMesh to_frame(const CovarianceMesh& mesh) const;
  /// `mesh`'s Gaussians in the frame, as to_frame gives them.
  FramedGaussians gaussians_in_frame(const CovarianceMesh& mesh) const;
  /// The same for the `vertices` of `mesh` only, written into `framed` (of the same vertex count);
  /// returns those among them whose Gaussian in the frame is not the one `framed` held (in order).
  std::vector<int> to_frame(const CovarianceMesh& mesh, const std::vector<int>& vertices,
                            FramedGaussians& framed) const;
  /// One mean or covariance in the frame.
  Vec3 mean_in_frame(const Vec3& mean) const;
  Mat3 covariance_in_frame(const Mat3& covariance) const;
  /// World from frame as a matrix: x = centre + unit · rotation · x'.
  glm::dmat4 world_from_frame() const;
  /// Whether the frame's axes are turned from the world's.
  bool turned() const { return rotation != glm::dmat3(1.0); }
  /// `rotation` as an Eigen matrix.
  Mat3 rotation_matrix() const;
  glm::dvec3 to_world(const glm::dvec3& p) const { return centre + unit * (turned() ? rotation * p : p); }
  /// A direction (a normal) in the frame, in the world.
  glm::dvec3 direction_to_world(const glm::dvec3& d) const { return turned() ? rotation * d : d; }
  /// A world point in the frame, as mean_in_frame maps it.
  glm::dvec3 to_frame(const glm::dvec3& world) const;
};

/// A frame's map of means and covariances, set up once for a pass over many vertices: the values of
/// mean_in_frame and covariance_in_frame bit for bit, the common frame (not turned) inline.
class FrameMap {
public:
  explicit FrameMap(const NormalisedFrame& frame)
      : frame_(frame),
        centre_(frame.centre.x, frame.centre.y, frame.centre.z),
        scale_(1.0 / frame.unit),
        turned_(frame.turned()) {}
  Vec3 mean(const Vec3& mean) const { return turned_ ? frame_.mean_in_frame(mean) : Vec3((mean - centre_) * scale_); }
  Mat3 covariance(const Mat3& covariance) const {
    return turned_ ? frame_.covariance_in_frame(covariance) : Mat3(covariance * (scale_ * scale_));
  }

private:
  const NormalisedFrame& frame_;
  Vec3 centre_;
  double scale_;
  bool turned_;
};

/// `mesh`'s Gaussians in `frame` (as gaussians_in_frame gives them) written into `framed`, and in the
/// same pass the vertices (increasing) whose Gaussian there is not `before`'s at their `origin`: the
/// changed and the new ones (origin −1). An empty `origin` keeps each vertex's number.
std::vector<int> changed_gaussians(const FramedGaussians& before, const CovarianceMesh& mesh,
                                   const NormalisedFrame& frame, const std::vector<int>& origin,
                                   FramedGaussians& framed);

}  // namespace gps
