#pragma once
// Plain polygon meshes from OBJ, OFF and STL (ASCII or binary); covariances are left as identity
// for the caller to infer (core/mesh/inference.h).
#include <string>

#include "core/mesh/covariance_mesh.h"

namespace gps {

/// Parses OBJ text (v and f records; f accepts v/vt/vn and negative indices; other records are skipped).
CovarianceMesh parse_obj(const std::string& data, const std::string& source);

/// Parses OFF text (optionally with the 'OFF' keyword missing and '#' comments).
CovarianceMesh parse_off(const std::string& data, const std::string& source);

/// Parses STL, ASCII or binary; triangle corners at identical positions are welded into one vertex.
CovarianceMesh parse_stl(const std::string& data, const std::string& source);

}  // namespace gps
