#include "core/limit_masks.h"

#include "core/linalg.h"
#include "core/vertex_mask.h"

namespace gps {

bool all_quads(const PolygonTopology& t) {
  for (int f = 0; f < t.n_faces(); ++f)
    if (t.face_size(f) != 4) return false;
  return true;
}

namespace {
// Each vertex's mask applied to the values, on all cores for a large mesh (one mask per thread).
template <class T, class MaskOf>
std::vector<T> apply_masks(int n_vertices, const std::vector<T>& p, MaskOf mask_of) {
  std::vector<T> out(p.size());
#pragma omp parallel if (n_vertices >= kParallelFaces)
  {
    VertexMask mask;
#pragma omp for
    for (int v = 0; v < n_vertices; ++v) {
      mask_of(v, mask);
      out[size_t(v)] = mask.apply(p);
    }
  }
  return out;
}
}  // namespace

template <class T>
std::vector<T> catmull_clark_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& p) {
  return apply_masks(t.n_vertices, p, [&](int v, VertexMask& mask) { catmull_clark_limit_mask(t, c, v, mask); });
}

template <class T>
std::vector<T> loop_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& p, LoopBeta kind) {
  return apply_masks(t.n_vertices, p, [&](int v, VertexMask& mask) { loop_limit_mask(c, v, kind, mask); });
}

template std::vector<Vec3> catmull_clark_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Vec3>&);
template std::vector<Dual> catmull_clark_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Dual>&);
template std::vector<Vec3> loop_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Vec3>&, LoopBeta);
template std::vector<Dual> loop_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Dual>&, LoopBeta);
template std::vector<Eigen::VectorXd> loop_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Eigen::VectorXd>&, LoopBeta);

}  // namespace gps
