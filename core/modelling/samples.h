#pragma once
// Built-in covariance meshes, generated procedurally (the cube, cones, cylinder, sphere and torus from
// the shapes of core/modelling/shapes.h, as the primitives are).
#include <string>
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

/// The names make_sample() knows, in a stable order.
std::vector<std::string> sample_names();

/// A one-line description of a sample.
std::string sample_description(const std::string& name);

/// The named sample; `size` is the approximate face count of "grid", "sphere" and "icosphere" (ignored by the
/// others). Throws a usage error for an unknown name or a size outside 1..4,000,000.
CovarianceMesh make_sample(const std::string& name, int size = 0);

/// Whether make_sample() uses `size` for this sample ("grid", "sphere", "icosphere").
bool sample_has_size(const std::string& name);

}  // namespace gps
