#include "core/plans/patch_layout.h"

namespace gps {

PatchLayout make_patch_layout(const PolygonTopology& faces) {
  PatchLayout layout;
  layout.first_patch.reserve(size_t(faces.n_faces()) + 1);
  int next = 0;
  for (int f = 0; f < faces.n_faces(); ++f) {
    layout.first_patch.push_back(next);
    const int n = faces.face_size(f);
    next += n == 4 ? 1 : n;
  }
  layout.first_patch.push_back(next);
  return layout;
}

}  // namespace gps
