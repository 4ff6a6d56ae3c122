#include "core/reference/limit_masks.h"

#include <algorithm>

#include "core/mesh/linalg.h"
#include "core/reference/crease_rules.h"
#include "core/reference/dart_masks.h"
#include "core/reference/vertex_mask.h"

namespace gps {

bool all_quads(const PolygonTopology& t) {
  for (int f = 0; f < t.n_faces(); ++f)
    if (t.face_size(f) != 4) return false;
  return true;
}

namespace {
// Each vertex v < n: put(v, its mask applied to the values), on all cores for a large mesh. A block
// of vertices at a time: first all their masks, then all their sums, then put: the memory lookups
// of different vertices, independent, overlap instead of each waiting behind its vertex's work.
template <class T, class MaskOf>
void apply_masks(int n, const std::vector<T>& p, MaskOf mask_of, const PutLimit<T>& put) {
  constexpr int kBlock = 64;
#pragma omp parallel if (n >= kParallelFaces)
  {
    std::vector<VertexMask> masks(kBlock);  // one block per thread, storage reused
    std::vector<T> sums(kBlock);
#pragma omp for
    for (int begin = 0; begin < n; begin += kBlock) {
      const int end = std::min(n, begin + kBlock);
      for (int v = begin; v < end; ++v) mask_of(v, masks[size_t(v - begin)]);
      for (int v = begin; v < end; ++v) sums[size_t(v - begin)] = masks[size_t(v - begin)].apply(p);
      for (int v = begin; v < end; ++v) put(v, sums[size_t(v - begin)]);
    }
  }
}

template <class T>
PutLimit<T> store_in(std::vector<T>& out) {
  return [&out](int v, const T& limit) { out[size_t(v)] = limit; };
}

// The limit mask under the rule of v's remaining sharpness: a crease, a corner, or a dart of an
// infinitely sharp edge (core/reference/dart_masks.h, quads or triangles with β `kind`); false
// for a smooth vertex or a semi-sharp dart, whose scheme's smooth mask applies.
bool sharp_limit_mask(const PolygonTopology& t, const MeshConnectivity& c, const CreaseLevel& creases, int v,
                      bool quads, LoopBeta kind, VertexMask& mask) {
  int a = -1, b = -1;
  const VertexRule rule = vertex_rule(c, creases, v, &a, &b);
  if (rule == VertexRule::smooth) return false;
  if (rule == VertexRule::dart) return dart_limit_mask(t, c, creases, v, quads, kind, mask);
  sharp_vertex_mask(rule, v, a, b, BoundaryRule::limit, mask);
  return true;
}
}  // namespace

template <class T>
void catmull_clark_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& p, int n,
                         const PutLimit<T>& put, const CreaseLevel* creases) {
  if (!creases || creases->empty()) {
    apply_masks(
        n, p, [&](int v, VertexMask& mask) { catmull_clark_limit_mask(t, c, v, mask); }, put);
    return;
  }
  apply_masks(
      n, p,
      [&](int v, VertexMask& mask) {
        if (!sharp_limit_mask(t, c, *creases, v, true, LoopBeta::loop, mask))
          catmull_clark_smooth_limit_mask(t, c, v, mask);
      },
      put);
}

template <class T>
void loop_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& p, LoopBeta kind,
                const PutLimit<T>& put, const CreaseLevel* creases) {
  if (!creases || creases->empty()) {
    apply_masks(
        t.n_vertices, p, [&](int v, VertexMask& mask) { loop_limit_mask(c, v, kind, mask); }, put);
    return;
  }
  apply_masks(
      t.n_vertices, p,
      [&](int v, VertexMask& mask) {
        if (!sharp_limit_mask(t, c, *creases, v, false, kind, mask)) loop_smooth_limit_mask(c, v, kind, mask);
      },
      put);
}

template <class T>
std::vector<T> catmull_clark_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& p) {
  std::vector<T> out(p.size());
  catmull_clark_limit(t, c, p, t.n_vertices, store_in(out));
  return out;
}

template <class T>
std::vector<T> loop_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& p, LoopBeta kind) {
  std::vector<T> out(p.size());
  loop_limit(t, c, p, kind, store_in(out));
  return out;
}

template std::vector<Vec3> catmull_clark_limit(const PolygonTopology&, const MeshConnectivity&,
                                               const std::vector<Vec3>&);
template std::vector<Dual> catmull_clark_limit(const PolygonTopology&, const MeshConnectivity&,
                                               const std::vector<Dual>&);
template std::vector<Vec3> loop_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Vec3>&,
                                      LoopBeta);
template std::vector<Dual> loop_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Dual>&,
                                      LoopBeta);
template std::vector<Eigen::VectorXd> loop_limit(const PolygonTopology&, const MeshConnectivity&,
                                                 const std::vector<Eigen::VectorXd>&, LoopBeta);
template void catmull_clark_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Vec3>&, int,
                                  const PutLimit<Vec3>&, const CreaseLevel*);
template void catmull_clark_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Dual>&, int,
                                  const PutLimit<Dual>&, const CreaseLevel*);
template void loop_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Vec3>&, LoopBeta,
                         const PutLimit<Vec3>&, const CreaseLevel*);
template void loop_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Dual>&, LoopBeta,
                         const PutLimit<Dual>&, const CreaseLevel*);

}  // namespace gps
