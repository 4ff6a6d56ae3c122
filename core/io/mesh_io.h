#pragma once
// Reading and writing meshes by file extension (docs/design.md §4).
#include <string>

#include "core/mesh/covariance_mesh.h"

namespace gps {

struct ImportOptions {
  enum class Covariance { infer, isotropic } covariance = Covariance::infer;
  double bias = 0.05;            // for inference (GPS paper Eq. 16)
  double isotropic_scale = 0.5;  // σ = scale × mean edge length at the vertex
};

/// Reads .ply (a covariance PLY keeps its covariances; a plain one gets them from `options`),
/// .obj, .off, .stl (covariances from `options`). Throws gps::Error naming the file, also for a mesh
/// without faces (every use of a mesh needs its surface).
CovarianceMesh read_mesh(const std::string& path, const ImportOptions& options = {});

/// Writes .ply (covariances kept; ASCII or binary little endian) or .obj (positions and faces),
/// atomically: a temporary file beside the target, then a rename.
void write_mesh(const std::string& path, const CovarianceMesh& mesh, bool binary = false);

/// The lower-case extension of a path, with the dot (".ply"), or "" when there is none.
std::string extension_of(const std::string& path);

}  // namespace gps
