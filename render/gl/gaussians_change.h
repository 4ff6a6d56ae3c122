#pragma once
// A change's Gaussians against those a renderer holds, for a change that keeps every old vertex's
// number (an operation that only adds vertices, or its undo): the changed and new vertices and their
// values in the frame, found without writing the others, and then written into the Gaussians held.
// Where numbers move, changed_gaussians (render/gl/normalised_frame.h) writes every vertex anew.
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "render/gl/normalised_frame.h"

namespace gps {

struct GaussiansChange {
  std::vector<int> changed;       // increasing: the vertices changed_gaussians lists
  std::vector<Mat3> covariances;  // per changed vertex, in the frame
  std::vector<Vec3> means;
  size_t n_vertices = 0;  // the mesh's
};

/// Whether a change whose vertices came from `origin` (as SurfaceRenderer::set_mesh takes it; empty:
/// the same) keeps the number of every vertex of the `n_before` that stays among the mesh's `n`.
bool keeps_vertex_numbers(const std::vector<int>& origin, size_t n_before, size_t n);

/// For such a change from the Gaussians `before` (in `frame`) to `mesh`'s: the vertices whose Gaussian
/// in the frame is not `before`'s at their origin, as changed_gaussians lists them, with their values.
GaussiansChange gaussians_change(const FramedGaussians& before, const CovarianceMesh& mesh,
                                 const NormalisedFrame& frame, const std::vector<int>& origin);

/// `framed`, the `before` of gaussians_change, made the mesh's as changed_gaussians gives them: sized
/// to its vertices, a new vertex that did not change given its origin's value, the changed written.
void apply_gaussians_change(const GaussiansChange& change, const std::vector<int>& origin, FramedGaussians& framed);

}  // namespace gps
