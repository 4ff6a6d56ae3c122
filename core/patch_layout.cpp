#include "core/patch_layout.h"

namespace gps {

std::vector<int> face_vertices(const PolyMesh& mesh, PolyMesh::FaceHandle f) {
  std::vector<int> out;
  for (const auto v : mesh.fv_range(f)) out.push_back(v.idx());
  return out;
}

bool is_quad_mesh(const PolyMesh& mesh) {
  for (const auto f : mesh.faces())
    if (mesh.valence(f) != 4) return false;
  return true;
}

PatchLayout make_patch_layout(const PolyMesh& mesh) {
  const bool split = !is_quad_mesh(mesh);
  PatchLayout layout;
  layout.first_patch.reserve(mesh.n_faces() + 1);
  int next = 0;
  for (const auto f : mesh.faces()) {
    layout.first_patch.push_back(next);
    const int n = int(mesh.valence(f));
    next += (n == 4 && !split) ? 1 : n;
  }
  layout.first_patch.push_back(next);
  return layout;
}

}  // namespace gps
