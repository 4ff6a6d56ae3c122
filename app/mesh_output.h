#pragma once
// Writing a command's mesh, and saying what the format cannot keep of it.
#include <string>

#include "core/mesh/covariance_mesh.h"

namespace gps {

/// write_mesh (core/io/mesh_io.h), then, unless `quiet`, a note on stderr of what the file's format
/// cannot keep (unsaved_sharpness_note: a glTF's creases and corners).
void write_mesh_noting(const std::string& path, const CovarianceMesh& mesh, bool binary, bool quiet = false);

}  // namespace gps
