#include "app/mesh_output.h"

#include <iostream>

#include "core/io/mesh_io.h"

namespace gps {

void write_mesh_noting(const std::string& path, const CovarianceMesh& mesh, bool binary, bool quiet) {
  write_mesh(path, mesh, binary);
  if (const std::string note = unsaved_sharpness_note(path, mesh); !note.empty() && !quiet)
    std::cerr << "note: " << note << "\n";
}

}  // namespace gps
