#include "core/plans/patch_layout.h"

namespace gps {

std::vector<int> face_vertices(const PolyMesh& mesh, PolyMesh::FaceHandle f) {
  std::vector<int> out;
  for (const auto v : mesh.fv_range(f)) out.push_back(v.idx());
  return out;
}

PatchLayout make_patch_layout(const PolyMesh& mesh) {
  PatchLayout layout;
  layout.first_patch.reserve(mesh.n_faces() + 1);
  int next = 0;
  for (const auto f : mesh.faces()) {
    layout.first_patch.push_back(next);
    const int n = int(mesh.valence(f));
    next += n == 4 ? 1 : n;
  }
  layout.first_patch.push_back(next);
  return layout;
}

}  // namespace gps
