#include "core/mesh/spare_connectivity.h"

#include <utility>

namespace gps {

namespace {

// The largest spare kept, in corners: a mesh of about a million quads.
constexpr size_t kSpareCorners = size_t(5) << 20;

// The spare, and whether this thread's spare is gone (a connectivity let go while the thread's
// objects are destroyed, after the spare, is let go with it): a bool is never destroyed.
thread_local bool spare_gone = false;
struct Spare {
  MeshConnectivity connectivity;
  ~Spare() { spare_gone = true; }
};
thread_local Spare spare;

}  // namespace

void keep_spare_connectivity(MeshConnectivity&& c) {
  if (spare_gone || c.face_edges.size() > kSpareCorners) return;
  if (c.face_edges.size() < spare.connectivity.face_edges.size()) return;
  spare.connectivity = std::move(c);
}

MeshConnectivity take_spare_connectivity() {
  if (spare_gone) return {};
  return std::exchange(spare.connectivity, MeshConnectivity{});
}

}  // namespace gps
