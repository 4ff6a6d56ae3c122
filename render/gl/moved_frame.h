#pragma once
// A mesh moved whole by one map x ↦ s·R·x + t (s > 0, R a rotation): GPS commutes with affine maps
// (docs/design.md §1), so its surface is the one already evaluated, moved by that map. A renderer that
// finds the map moves its frame (render/gl/normalised_frame.h) with the mesh and evaluates nothing again.
#include <optional>

#include "core/mesh/covariance_mesh.h"
#include "render/gl/normalised_frame.h"

namespace gps {

/// The frame in which every Gaussian of `mesh` is, to within rounding, the one `framed` holds in
/// `frame` at the same vertex number, where `mesh` is `framed` moved whole by a rotation, a positive
/// uniform scale and a translation; nullopt otherwise (any other edit, a mirror, another vertex
/// count). Its Gaussians framed there are written into `moved`.
std::optional<NormalisedFrame> moved_frame(const NormalisedFrame& frame, const FramedGaussians& framed,
                                           const CovarianceMesh& mesh, FramedGaussians& moved);

}  // namespace gps
