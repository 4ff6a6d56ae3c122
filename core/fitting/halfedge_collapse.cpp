#include "core/fitting/halfedge_collapse.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <OpenMesh/Tools/Utils/HeapT.hh>

namespace gps {
namespace {

using VertexHandle = CollapseMesh::VertexHandle;
using HalfedgeHandle = CollapseMesh::HalfedgeHandle;

/// OpenMesh's binary heap of vertices by key (as its DecimaterT keeps), which knows where each
/// vertex is in it.
class VertexHeap {
  struct Interface {
    std::vector<float>* key;
    std::vector<int>* position;
    bool less(VertexHandle a, VertexHandle b) const { return (*key)[size_t(a.idx())] < (*key)[size_t(b.idx())]; }
    bool greater(VertexHandle a, VertexHandle b) const { return (*key)[size_t(a.idx())] > (*key)[size_t(b.idx())]; }
    int get_heap_position(VertexHandle v) const { return (*position)[size_t(v.idx())]; }
    void set_heap_position(VertexHandle v, int at) { (*position)[size_t(v.idx())] = at; }
  };

public:
  explicit VertexHeap(size_t vertices) : key_(vertices, 0), position_(vertices, -1), heap_(Interface{&key_, &position_}) {
    heap_.reserve(vertices);
  }
  bool empty() const { return heap_.empty(); }
  int front() const { return heap_.front().idx(); }
  void set(int v, float key) {
    key_[size_t(v)] = key;
    if (heap_.is_stored(VertexHandle(v)))
      heap_.update(VertexHandle(v));
    else
      heap_.insert(VertexHandle(v));
  }
  void remove(int v) {
    if (heap_.is_stored(VertexHandle(v))) heap_.remove(VertexHandle(v));
  }

private:
  std::vector<float> key_;
  std::vector<int> position_;
  OpenMesh::Utils::HeapT<VertexHandle, Interface> heap_;
};

class Decimation {
public:
  Decimation(CollapseMesh& mesh, const HalfedgeCollapses& collapses)
      : mesh_(mesh),
        collapses_(collapses),
        min_cos_(std::cos(collapses.max_normal_deviation_degrees * M_PI / 180)),
        heap_(mesh.n_vertices()),
        target_(mesh.n_vertices()),
        forbidden_(mesh.n_halfedges(), 0),
        mark_(mesh.n_vertices(), 0) {}

  size_t run(size_t target_vertices) {
    size_t vertices = mesh_.n_vertices();
    for (const auto v : mesh_.vertices()) update(v);
    const size_t asked = vertices - std::min(vertices, target_vertices);
    const size_t report_every = std::max<size_t>(1, asked / 100);
    size_t done = 0;
    std::vector<VertexHandle> support;
    while (vertices > target_vertices && !heap_.empty()) {
      const VertexHandle v0(heap_.front());
      const HalfedgeHandle h = target_[size_t(v0.idx())];
      if (!allowed(h)) {
        forbidden_[size_t(h.idx())] = 1;
        choose(v0);
        continue;
      }
      const VertexHandle v1 = mesh_.to_vertex_handle(h);
      heap_.remove(v0.idx());
      support.assign(mesh_.vv_begin(v0), mesh_.vv_end(v0));
      mesh_.collapse(h);
      --vertices;
      collapses_.collapsed(v0, v1);
      // As OpenMesh's DecimaterT: the vertices of v0's former one-ring (v1 among them) choose afresh.
      for (const VertexHandle w : support) update(w);
      if (collapses_.progress && ++done % report_every == 0 &&
          !collapses_.progress(std::min(1.0, double(done) / double(asked))))
        throw Cancelled();
    }
    return vertices;
  }

private:
  /// Whether `h`'s collapse passes the cheap tests of its ends' status, which the priority heap
  /// applies at once: an unlocked start, along a feature edge from a feature vertex, and along the
  /// boundary from a boundary vertex.
  bool may_move(HalfedgeHandle h) const {
    const VertexHandle v0 = mesh_.from_vertex_handle(h);
    if (mesh_.status(v0).locked()) return false;
    if (mesh_.status(v0).feature() && !mesh_.status(mesh_.edge_handle(h)).feature()) return false;
    if (mesh_.is_boundary(v0) && !mesh_.is_boundary(mesh_.edge_handle(h))) return false;
    return !mesh_.is_boundary(v0) || mesh_.is_boundary(mesh_.to_vertex_handle(h));
  }

  /// Puts `v` on the heap with its best collapse that is not known to be forbidden, or takes it off.
  void choose(VertexHandle v) {
    float best = INFINITY;
    HalfedgeHandle chosen;
    for (const auto h : mesh_.voh_range(v)) {
      if (forbidden_[size_t(h.idx())] || !may_move(h)) continue;
      const float priority = collapses_.priority(v, mesh_.to_vertex_handle(h));
      if (priority >= 0 && priority < best) best = priority, chosen = h;
    }
    target_[size_t(v.idx())] = chosen;
    if (chosen.is_valid())
      heap_.set(v.idx(), best);
    else
      heap_.remove(v.idx());
  }

  /// `v`'s collapses afresh, as its one-ring changed.
  void update(VertexHandle v) {
    for (const auto h : mesh_.voh_range(v)) forbidden_[size_t(h.idx())] = 0;
    choose(v);
  }

  /// The tests of OpenMesh's TriConnectivity::is_collapse_ok and BaseDecimaterT::is_collapse_legal
  /// that depend on the one-rings, and its normal flipping module's.
  bool allowed(HalfedgeHandle v0v1) {
    const HalfedgeHandle v1v0 = mesh_.opposite_halfedge_handle(v0v1);
    const VertexHandle v0 = mesh_.from_vertex_handle(v0v1), v1 = mesh_.to_vertex_handle(v0v1);
    VertexHandle vl, vr;
    if (!mesh_.is_boundary(v0v1)) {
      const HalfedgeHandle h1 = mesh_.next_halfedge_handle(v0v1), h2 = mesh_.next_halfedge_handle(h1);
      vl = mesh_.to_vertex_handle(h1);
      if (mesh_.is_boundary(mesh_.opposite_halfedge_handle(h1)) && mesh_.is_boundary(mesh_.opposite_halfedge_handle(h2)))
        return false;
    }
    if (!mesh_.is_boundary(v1v0)) {
      const HalfedgeHandle h1 = mesh_.next_halfedge_handle(v1v0), h2 = mesh_.next_halfedge_handle(h1);
      vr = mesh_.to_vertex_handle(h1);
      if (mesh_.is_boundary(mesh_.opposite_halfedge_handle(h1)) && mesh_.is_boundary(mesh_.opposite_halfedge_handle(h2)))
        return false;
    }
    if (vl.is_valid() && vl == vr) return false;
    if (mesh_.is_boundary(v0) && mesh_.is_boundary(v1) && !mesh_.is_boundary(v0v1) && !mesh_.is_boundary(v1v0))
      return false;
    // The link condition: the one-rings of v0 and v1 share only vl and vr.
    ++stamp_;
    for (const auto w : mesh_.vv_range(v1)) mark_[size_t(w.idx())] = stamp_;
    for (const auto w : mesh_.vv_range(v0))
      if (mark_[size_t(w.idx())] == stamp_ && w != vl && w != vr) return false;
    if (vl.is_valid() && vr.is_valid() && mesh_.valence(vl) == 3 && mesh_.valence(vr) == 3 &&
        mesh_.find_halfedge(vl, vr).is_valid())
      return false;
    // At least two faces at v0.
    if (mesh_.cw_rotated_halfedge_handle(mesh_.cw_rotated_halfedge_handle(v0v1)) == v0v1) return false;
    return keeps_normals(v0v1);
  }

  /// Whether moving v0 onto v1 turns the normal of no face around v0 but the two collapsed ones by
  /// more than the limit.
  bool keeps_normals(HalfedgeHandle v0v1) const {
    const auto fl = mesh_.face_handle(v0v1), fr = mesh_.face_handle(mesh_.opposite_halfedge_handle(v0v1));
    const VertexHandle v0 = mesh_.from_vertex_handle(v0v1);
    const auto p1 = mesh_.point(mesh_.to_vertex_handle(v0v1));
    for (const auto h : mesh_.voh_range(v0)) {
      const auto f = mesh_.face_handle(h);
      if (!f.is_valid() || f == fl || f == fr) continue;
      const auto hn = mesh_.next_halfedge_handle(h);
      const auto a = mesh_.point(mesh_.to_vertex_handle(h)), b = mesh_.point(mesh_.to_vertex_handle(hn));
      const auto before = OpenMesh::cross(a - mesh_.point(v0), b - mesh_.point(v0));
      const auto after = OpenMesh::cross(a - p1, b - p1);
      const double lengths = double(before.norm()) * double(after.norm());
      if (!(lengths > 0) || double(OpenMesh::dot(before, after)) < min_cos_ * lengths) return false;
    }
    return true;
  }

  CollapseMesh& mesh_;
  const HalfedgeCollapses& collapses_;
  const double min_cos_;
  VertexHeap heap_;
  std::vector<HalfedgeHandle> target_;
  std::vector<uint8_t> forbidden_;
  std::vector<uint32_t> mark_;
  uint32_t stamp_ = 0;
};

}  // namespace

size_t collapse_halfedges(CollapseMesh& mesh, size_t target_vertices, const HalfedgeCollapses& collapses) {
  return Decimation(mesh, collapses).run(target_vertices);
}

}  // namespace gps
